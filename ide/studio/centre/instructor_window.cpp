#include "ide/studio/centre/instructor_window.h"

#include "trainer/station/profile.h"
#include "trainer/training/faults.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMenu>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QSplitter>
#include <QSysInfo>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace studio {

namespace centre = trainer::centre;

namespace {

QString num(double v, int decimals) { return QLocale().toString(v, 'f', decimals); }

}  // namespace

InstructorWindow::InstructorWindow(const centre::BusOptions& bus, const QString& keyFile, QWidget* parent)
    : QMainWindow(parent), m_keyLabel(new QLabel), m_table(new QTableWidget(0, ColumnCount)),
      m_view(new DisplayView(nullptr, DisplayView::Centre)), m_logTitle(new QLabel), m_log(new QPlainTextEdit),
      m_reply(new QLabel), m_clearMenu(new QMenu(this)), m_poll(new QTimer(this))
{
    setObjectName("InstructorWindow");
    auto* central = new QWidget;
    auto* layout = new QVBoxLayout(central);
    m_keyLabel->setObjectName("KeyLabel");
    m_keyLabel->setWordWrap(true);
    layout->addWidget(m_keyLabel);

    m_table->setObjectName("StationTable");
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(ColWarnings, QHeaderView::Stretch);
    connect(m_table, &QTableWidget::itemSelectionChanged, this, &InstructorWindow::onSelection);

    // the commands
    auto* buttons = new QHBoxLayout;
    const auto makeButton = [&](const char* name) {
        auto* b = new QPushButton;
        b->setObjectName(QString::fromLatin1(name));
        buttons->addWidget(b);
        return b;
    };
    m_start = makeButton("StartButton");
    m_pause = makeButton("PauseButton");
    m_resume = makeButton("ResumeButton");
    m_reset = makeButton("ResetButton");
    m_stop = makeButton("StopButton");
    m_inject = makeButton("InjectButton");
    m_clear = makeButton("ClearButton");
    m_clear->setMenu(m_clearMenu);
    buttons->addStretch(1);
    connect(m_start, &QPushButton::clicked, this, &InstructorWindow::startDialog);
    connect(m_pause, &QPushButton::clicked, this, [this] { sendCommand("pause"); });
    connect(m_resume, &QPushButton::clicked, this, [this] { sendCommand("resume"); });
    connect(m_reset, &QPushButton::clicked, this, [this] { sendCommand("reset"); });
    connect(m_stop, &QPushButton::clicked, this, [this] { sendCommand("stop"); });
    connect(m_inject, &QPushButton::clicked, this, &InstructorWindow::faultDialog);
    connect(m_clearMenu, &QMenu::aboutToShow, this, &InstructorWindow::fillClearMenu);

    // the selected station: its machine and its events
    m_view->setMinimumSize(480, 300);
    auto* logBox = new QWidget;
    auto* logLayout = new QVBoxLayout(logBox);
    logLayout->setContentsMargins(0, 0, 0, 0);
    logLayout->addWidget(m_logTitle);
    m_log->setObjectName("EventLog");
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(1000);
    logLayout->addWidget(m_log);
    auto* below = new QSplitter(Qt::Horizontal);
    below->addWidget(m_view);
    below->addWidget(logBox);
    below->setStretchFactor(0, 3);
    below->setStretchFactor(1, 2);
    auto* split = new QSplitter(Qt::Vertical);
    split->addWidget(m_table);
    auto* lower = new QWidget;
    auto* lowerLayout = new QVBoxLayout(lower);
    lowerLayout->setContentsMargins(0, 0, 0, 0);
    lowerLayout->addLayout(buttons);
    m_reply->setObjectName("ReplyLabel");
    m_reply->setWordWrap(true);
    m_reply->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lowerLayout->addWidget(m_reply);
    lowerLayout->addWidget(below, 1);
    split->addWidget(lower);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 3);
    layout->addWidget(split, 1);
    setCentralWidget(central);

    // the key: without one (or with one that cannot be used) the window only watches
    if (!keyFile.isEmpty()) {
        QString error;
        if (!m_key.load(keyFile, &error) || !m_key.isCentreKey(keyFile, &error)) {
            m_key = {};
            m_keyProblem = error;
        }
    }
    // the network
    centre::BusOptions o = bus;
    o.reads = centre::TopicAnnounce | centre::TopicState | centre::TopicEvent | centre::TopicReply;
    o.key = m_key;  // checks what the stations say: without it, nothing is shown
    // its name: the one given; with DDS Security instructor@HOST, like `padrob instructor`
    // (its identity in the PKI); else one name per window, so that the stations' logs tell
    // two windows apart
    if (o.node.isEmpty()) {
        o.node = QStringLiteral("instructor@") + QSysInfo::machineHostName();
        if (o.securityDir.isEmpty()) o.node += QLatin1Char(':') + QString::number(QCoreApplication::applicationPid());
    }
    QString error;
    m_bus = centre::Bus::open(o, &error);
    if (m_bus) {
        m_nodeName = o.node.toStdString();
        m_node = std::make_unique<centre::InstructorNode>(*m_bus, m_nodeName, m_key, DisplayFeed::kSilentAfter);
        m_node->announce();
        m_poll->setTimerType(Qt::PreciseTimer);
        connect(m_poll, &QTimer::timeout, this, &InstructorWindow::poll);
        m_poll->start(4);  // states come at 60 Hz: the live view misses none
    } else {
        m_busError = error;
    }
    m_view->setFeed(&m_feed);
    retranslate();
    refreshButtons();
    resize(1400, 900);
}

InstructorWindow::~InstructorWindow()
{
    m_view->setFeed(nullptr);
    if (m_bus && m_node) m_bus->withdraw(m_nodeName);
}

std::string InstructorWindow::presenceOf(const std::string& name, const centre::StationView& v) const
{
    const auto it = m_left.find(name);
    return it != m_left.end() && it->second == v.announce.startedMs ? std::string("left") : v.presence;
}

QString InstructorWindow::replyText() const { return m_reply->text(); }

QPushButton* InstructorWindow::button(const QString& objectName) const
{
    return findChild<QPushButton*>(objectName);
}

const centre::StationView* InstructorWindow::selectedView() const
{
    if (!m_node || m_selected.empty()) return nullptr;
    const auto it = m_node->stations().find(m_selected);
    return it == m_node->stations().end() ? nullptr : &it->second;
}

bool InstructorWindow::selectStation(const QString& station)
{
    for (int r = 0; r < m_table->rowCount(); ++r) {
        const QTableWidgetItem* it = m_table->item(r, ColStation);
        if (it && it->text() == station) {
            m_table->selectRow(r);
            return true;
        }
    }
    return false;
}

void InstructorWindow::onSelection()
{
    const QList<QTableWidgetItem*> items = m_table->selectedItems();
    std::string name;
    if (!items.isEmpty()) {
        const QTableWidgetItem* it = m_table->item(items.front()->row(), ColStation);
        if (it) name = it->text().toStdString();
    }
    if (name == m_selected) return;
    m_selected = name;
    m_feed.setStation(name);
    m_fedSeq = ~0ull;
    m_fedSim = -1;
    m_fedStarted = 0;
    m_logCount = 0;
    m_logLastSeq = 0;
    m_log->clear();
    poll();
    refreshLog();
    refreshButtons();
    retranslate();
}

void InstructorWindow::poll()
{
    if (!m_node) return;
    const double now = centreClock();
    m_node->poll(now);
    for (const auto& [name, v] : m_node->stations()) {
        if (v.presence == "left") m_left[name] = v.announce.startedMs;
        else if (const auto it = m_left.find(name); it != m_left.end() && it->second != v.announce.startedMs)
            m_left.erase(it);  // announced again: back
    }
    // the selected station's announcement and each new state, to its live view
    if (const centre::StationView* v = selectedView()) {
        if (v->announce.startedMs != m_fedStarted && !v->announce.model.empty()) {
            m_fedStarted = v->announce.startedMs;
            m_feed.announce(v->announce);
        }
        if (v->hasState && (v->state.seq != m_fedSeq || v->state.simTime != m_fedSim)) {
            m_fedSeq = v->state.seq;
            m_fedSim = v->state.simTime;
            m_feed.push(v->state, now);
        }
        if (presenceOf(m_selected, *v) == "left") m_feed.withdraw(m_selected);
    }
    // the replies to the commands sent
    for (auto it = m_pending.begin(); it != m_pending.end();) {
        if (const auto r = m_node->reply(it->nonce)) {
            showOutcome({r->accepted ? Outcome::What::Done : Outcome::What::Refused, it->station, it->kind, r->message});
            it = m_pending.erase(it);
        } else if (now - it->sentS > 5.0) {
            showOutcome({Outcome::What::NoReply, it->station, it->kind, {}});
            it = m_pending.erase(it);
        } else {
            ++it;
        }
    }
    if (now - m_lastTable >= 0.2) {  // the table and the log five times a second
        m_lastTable = now;
        refreshTable();
        refreshLog();
        refreshButtons();
    }
}

void InstructorWindow::refreshTable()
{
    if (!m_node) return;
    const auto& stations = m_node->stations();
    const bool growing = m_table->rowCount() != int(stations.size());
    m_table->setRowCount(int(stations.size()));
    int row = 0;
    for (const auto& [name, v] : stations) {
        const centre::State& s = v.state;
        const std::string shown = presenceOf(name, v);
        QString presence = shown == "up" ? tr("up") : shown == "silent" ? tr("silent") : tr("left");
        QString status, warnings;
        const bool idle = centre::stationStatus(s.status) == centre::StationStatus::Idle;
        if (v.hasState) {
            switch (centre::stationStatus(s.status)) {
            case centre::StationStatus::Idle: status = tr("idle"); break;
            case centre::StationStatus::Running: status = tr("running"); break;
            case centre::StationStatus::Paused: status = tr("paused"); break;
            case centre::StationStatus::Ended: status = tr("ended"); break;
            case centre::StationStatus::Unknown: status = QString::fromStdString(s.status); break;
            }
            QStringList w;
            if (s.warnings & centre::WarnOverload) w << tr("overload");
            if (s.warnings & centre::WarnNearWorker) w << tr("near a worker");
            if (s.warnings & centre::WarnNearScene) w << tr("near the scene");
            if (s.warnings & centre::WarnRecordsOffline) w << tr("records offline");
            if (s.warnings & centre::WarnRecordsRefused) w << tr("records kept aside (journal refuses writes)");
            for (const QString& f : QString::fromStdString(s.faults).split(',', Qt::SkipEmptyParts)) {
                trainer::Fault::Kind k;
                const QString key = f.section(':', 0, 0), drive = f.section(':', 1);
                if (trainer::Fault::fromKey(key.toStdString(), &k))
                    w << (drive.isEmpty() ? trainer::Fault::label(k) : tr("%1 (%2)").arg(trainer::Fault::label(k), drive));
                else
                    w << f;
            }
            warnings = w.join(QStringLiteral(", "));
        }
        const QStringList cells{
            QString::fromStdString(name),
            presence,
            status,
            v.hasState ? QString::fromStdString(s.tutorial) : QString(),
            v.hasState ? QString::fromStdString(s.operatorCode) : QString(),
            v.hasState && !idle ? tr("%1 s").arg(num(s.attemptTime, 1)) : QString(),
            v.hasState && !idle ? num(s.score, 0) : QString(),
            v.hasState && s.goals > 0 ? tr("%1/%2").arg(s.goal).arg(s.goals) : QString(),
            warnings,
            v.hasState && v.latencyMs >= 0 ? tr("%1 ms").arg(num(v.latencyMs, 0)) : QString(),
        };
        for (int c = 0; c < ColumnCount; ++c) {
            QTableWidgetItem* it = m_table->item(row, c);
            if (!it) {
                it = new QTableWidgetItem;
                m_table->setItem(row, c, it);
            }
            if (it->text() != cells[c]) it->setText(cells[c]);
        }
        QTableWidgetItem* p = m_table->item(row, ColPresence);
        p->setForeground(shown == "up" ? QColor(0x1b, 0x7a, 0x2f) : shown == "silent" ? QColor(0xb3, 0x6b, 0x00)
                                                                                                 : QColor(0x80, 0x80, 0x80));
        m_table->item(row, ColWarnings)->setForeground(s.warnings ? QColor(0xb3, 0x26, 0x1e) : palette().text().color());
        ++row;
    }
    // the first station to appear is selected; a new row keeps the selection on its station
    if (m_selected.empty() && !stations.empty()) m_table->selectRow(0);
    else if (growing && !m_selected.empty()) selectStation(QString::fromStdString(m_selected));
}

void InstructorWindow::refreshLog()
{
    const centre::StationView* v = selectedView();
    if (!v) return;
    const std::uint64_t lastSeq = v->events.empty() ? 0 : v->events.back().seq;
    if (v->events.size() == m_logCount && lastSeq == m_logLastSeq) return;
    m_logCount = v->events.size();
    m_logLastSeq = lastSeq;
    QStringList lines;
    for (const centre::Event& e : v->events) {
        QString text = QString::fromStdString(e.text);
        if (text.isEmpty()) text = QString::fromStdString(e.kind + (e.detail.empty() ? "" : " " + e.detail));
        lines << tr("%1 s  %2").arg(num(e.t, 1), text);
    }
    m_log->setPlainText(lines.join('\n'));
    m_log->verticalScrollBar()->setValue(m_log->verticalScrollBar()->maximum());  // the latest last, in sight
}

void InstructorWindow::refreshButtons()
{
    const centre::StationView* v = selectedView();
    const bool can = canCommand() && v && presenceOf(m_selected, *v) == "up";
    const bool known = v && v->hasState;
    const centre::StationStatus status = known ? centre::stationStatus(v->state.status) : centre::StationStatus::Unknown;
    const bool active = centre::attemptOn(status);
    m_start->setEnabled(can && !v->announce.tutorials.empty());
    m_pause->setEnabled(can && status == centre::StationStatus::Running);
    m_resume->setEnabled(can && status == centre::StationStatus::Paused);
    m_reset->setEnabled(can && known && status != centre::StationStatus::Idle);
    m_stop->setEnabled(can && active);
    m_inject->setEnabled(can && active);
    m_clear->setEnabled(can && active && v->hasState && !v->state.faults.empty());
}

void InstructorWindow::retranslate()
{
    setWindowTitle(tr("Padrob instructor"));
    m_table->setHorizontalHeaderLabels({tr("Station"), tr("Presence"), tr("Status"), tr("Tutorial"), tr("Operator"),
                                        tr("Time"), tr("Score"), tr("Goals"), tr("Warnings and faults"),
                                        tr("Latency")});
    m_start->setText(tr("Start…"));
    m_pause->setText(tr("Pause"));
    m_resume->setText(tr("Resume"));
    m_reset->setText(tr("Reset"));
    m_stop->setText(tr("Stop"));
    m_inject->setText(tr("Inject fault…"));
    m_clear->setText(tr("Clear fault"));
    m_logTitle->setText(m_selected.empty() ? tr("Events") : tr("Events of %1 (latest last)").arg(selectedStation()));
    QString keyText;
    if (!m_busError.isEmpty()) {
        keyText = tr("Cannot join the training centre's network: %1").arg(m_busError);
        m_view->setProblem(keyText);
    } else if (m_key.isSet()) {
        keyText = tr("Centre key %1: commands are signed with it, and what the stations say is checked against it.")
                      .arg(m_key.fingerprint());
    } else if (!m_keyProblem.isEmpty()) {
        keyText = tr("The centre's key cannot be used (%1): what the stations say cannot be checked, so none of it "
                     "is shown, and no command can be sent.")
                      .arg(m_keyProblem);
    } else {
        keyText = tr("Without the centre's key (--centre-key FILE) what the stations say cannot be checked, so none "
                     "of it is shown, and no command can be sent.");
    }
    m_keyLabel->setText(keyText);
    m_keyLabel->setStyleSheet(m_key.isSet() && m_busError.isEmpty() ? QString() : QStringLiteral("color: #b3261e;"));
    // why the commands are off
    const QString why = canCommand() ? QString()
                        : !m_busError.isEmpty()
                            ? tr("Not connected to the training centre's network.")
                            : tr("Commands need the centre's key: start padrob-studio with --centre-key FILE.");
    for (QPushButton* b : {m_start, m_pause, m_resume, m_reset, m_stop, m_inject, m_clear}) b->setToolTip(why);
}

void InstructorWindow::changeEvent(QEvent* event)
{
    QMainWindow::changeEvent(event);
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        refreshTable();
        showOutcome(m_outcome);
        m_logCount = 0;  // the log again, its times in the new language's numbers
        m_logLastSeq = ~0ull;
        refreshLog();
    }
}

QString InstructorWindow::kindLabel(const std::string& kind) const
{
    if (kind == "start") return tr("Start");
    if (kind == "pause") return tr("Pause");
    if (kind == "resume") return tr("Resume");
    if (kind == "reset") return tr("Reset");
    if (kind == "stop") return tr("Stop");
    if (kind == "inject") return tr("Inject fault");
    if (kind == "clear") return tr("Clear fault");
    return QString::fromStdString(kind);
}

QString InstructorWindow::refusalText(const std::string& code)
{
    if (code == "bad-signature") return tr("the command was not signed with the key this station has.");
    if (code == "stale")
        return tr("the command was too old when it arrived: check that the computers' clocks agree.");
    if (code == "replay") return tr("the station has already taken this very command (a replay).");
    if (code == "too-long") return tr("a field of the command is longer than the centre allows.");
    if (code == "busy") return tr("the station has taken too many commands in the last 30 seconds; try again shortly.");
    if (code == "no-key") return tr("the station has no centre key and takes no commands.");
    if (code == "not-running") return tr("no attempt is running on the station.");
    if (code == "not-paused") return tr("the attempt is not paused.");
    if (code == "unknown-tutorial") return tr("the station does not have that tutorial.");
    if (code == "unknown-fault") return tr("the station does not know that fault.");
    if (code == "unknown-command") return tr("the station does not know that command.");
    return QString::fromStdString(code);  // the station's own words (a fault it cannot inject)
}

void InstructorWindow::sendCommand(const QString& kind, const QString& arg, const QString& arg2, double value)
{
    if (!canCommand() || m_selected.empty()) return;
    const std::uint64_t nonce =
        m_node->send(m_selected, kind.toStdString(), arg.toStdString(), arg2.toStdString(), value);
    if (nonce == 0) {
        showOutcome({Outcome::What::Unsent, m_selected, kind.toStdString(), m_bus->lastError().toStdString()});
        return;
    }
    m_pending.push_back(Pending{nonce, m_selected, kind.toStdString(), centreClock()});
    showOutcome({Outcome::What::Sent, m_selected, kind.toStdString(), {}});
}

void InstructorWindow::showOutcome(Outcome outcome)
{
    m_outcome = std::move(outcome);
    const Outcome& o = m_outcome;
    const QString what = tr("%1 on %2").arg(kindLabel(o.kind), QString::fromStdString(o.station));
    QString text;
    bool bad = false;
    switch (o.what) {
    case Outcome::What::None: break;
    case Outcome::What::Sent: text = tr("%1: sent, waiting for the station…").arg(what); break;
    case Outcome::What::Unsent:
        text = o.code.empty() ? tr("%1: could not be sent.").arg(what)
                              : tr("%1: could not be sent (%2).").arg(what, QString::fromStdString(o.code));
        bad = true;
        break;
    case Outcome::What::Done: text = tr("%1: done.").arg(what); break;
    case Outcome::What::Refused:
        text = tr("%1: refused, %2").arg(what, refusalText(o.code));
        bad = true;
        break;
    case Outcome::What::NoReply:
        text = tr("%1: no reply from the station in 5 s.").arg(what);
        bad = true;
        break;
    }
    m_reply->setText(text);
    m_reply->setStyleSheet(bad ? QStringLiteral("color: #b3261e;")
                           : o.what == Outcome::What::Done ? QStringLiteral("color: #1b7a2f;") : QString());
}

void InstructorWindow::startDialog()
{
    const centre::StationView* v = selectedView();
    if (!v || !canCommand()) return;
    auto* d = new QDialog(this);
    d->setObjectName("StartDialog");
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->setWindowTitle(tr("Start a tutorial on %1").arg(selectedStation()));
    auto* form = new QFormLayout(d);
    auto* tutorial = new QComboBox;
    tutorial->setObjectName("TutorialBox");
    for (const std::string& id : v->announce.tutorials) tutorial->addItem(QString::fromStdString(id));
    if (v->hasState) tutorial->setCurrentText(QString::fromStdString(v->state.tutorial));
    auto* op = new QLineEdit;
    op->setObjectName("OperatorEdit");
    op->setPlaceholderText(tr("guest"));
    form->addRow(tr("Tutorial:"), tutorial);
    form->addRow(tr("Operator code:"), op);
    auto* box = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    box->button(QDialogButtonBox::Ok)->setText(tr("Start"));
    form->addRow(box);
    connect(box, &QDialogButtonBox::accepted, d, &QDialog::accept);
    connect(box, &QDialogButtonBox::rejected, d, &QDialog::reject);
    connect(d, &QDialog::accepted, this, [this, tutorial, op] {
        sendCommand("start", tutorial->currentText(), op->text().trimmed());
    });
    d->open();
}

void InstructorWindow::faultDialog()
{
    if (!selectedView() || !canCommand()) return;
    using trainer::Fault;
    auto* d = new QDialog(this);
    d->setObjectName("FaultDialog");
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->setWindowTitle(tr("Inject a fault on %1").arg(selectedStation()));
    auto* form = new QFormLayout(d);
    auto* kind = new QComboBox;
    kind->setObjectName("FaultKind");
    for (Fault::Kind k : {Fault::Kind::HoseBurst, Fault::Kind::StuckValve, Fault::Kind::WorkerIn, Fault::Kind::PowerCut})
        kind->addItem(Fault::label(k), QString::fromLatin1(Fault::key(k)));
    // the drives: the model's, as the station names them (its NAME, else "C id")
    auto* drive = new QComboBox;
    drive->setObjectName("DriveBox");
    drive->setEditable(true);
    if (const auto b = m_feed.bundle()) {
        for (const trainer::DriveInfo& di : trainer::drivesOf(*b->model)) {
            const QString name = di.name.isEmpty() ? QStringLiteral("C %1").arg(di.jointId) : di.name;
            drive->addItem(di.label(), name);
        }
    }
    auto* opening = new QDoubleSpinBox;
    opening->setObjectName("OpeningBox");
    opening->setRange(-1, 1);
    opening->setSingleStep(0.1);
    opening->setValue(0.5);
    auto* where = new QWidget;
    auto* whereRow = new QHBoxLayout(where);
    whereRow->setContentsMargins(0, 0, 0, 0);
    QDoubleSpinBox* xyz[3];
    for (int i = 0; i < 3; ++i) {
        xyz[i] = new QDoubleSpinBox;
        xyz[i]->setObjectName(QStringLiteral("Worker%1").arg(QChar("XYZ"[i])));
        xyz[i]->setRange(-100, 100);
        xyz[i]->setDecimals(2);
        xyz[i]->setSuffix(tr(" m"));
        whereRow->addWidget(xyz[i]);
    }
    form->addRow(tr("Fault:"), kind);
    form->addRow(tr("Drive:"), drive);
    form->addRow(tr("Valve opening (−1 … 1):"), opening);
    form->addRow(tr("Where the worker walks to (x, y, z):"), where);
    auto* box = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    box->button(QDialogButtonBox::Ok)->setText(tr("Inject"));
    form->addRow(box);
    const auto showRows = [form, kind, drive, opening, where] {
        const QString k = kind->currentData().toString();
        form->setRowVisible(drive, k == "hose-burst" || k == "stuck-valve");
        form->setRowVisible(opening, k == "stuck-valve");
        form->setRowVisible(where, k == "worker-in");
    };
    showRows();
    connect(kind, &QComboBox::currentIndexChanged, d, showRows);
    connect(box, &QDialogButtonBox::accepted, d, &QDialog::accept);
    connect(box, &QDialogButtonBox::rejected, d, &QDialog::reject);
    connect(d, &QDialog::accepted, this, [this, kind, drive, opening, xyz] {
        const QString k = kind->currentData().toString();
        // the drive's name as the station knows it (typed, or the chosen entry's)
        QString driveName = drive->currentText().trimmed();
        if (drive->currentIndex() >= 0 && drive->itemText(drive->currentIndex()) == driveName)
            driveName = drive->currentData().toString();
        if (k == "hose-burst") sendCommand("inject", k, driveName);
        else if (k == "stuck-valve") sendCommand("inject", k, driveName, opening->value());
        else if (k == "worker-in")
            sendCommand("inject", k,
                        QStringLiteral("%1,%2,%3").arg(xyz[0]->value()).arg(xyz[1]->value()).arg(xyz[2]->value()));
        else sendCommand("inject", k);
    });
    d->open();
}

void InstructorWindow::fillClearMenu()
{
    m_clearMenu->clear();
    const centre::StationView* v = selectedView();
    if (!v || !v->hasState) return;
    for (const QString& f : QString::fromStdString(v->state.faults).split(',', Qt::SkipEmptyParts)) {
        const QString key = f.section(':', 0, 0), drive = f.section(':', 1);
        trainer::Fault::Kind k;
        const QString label = !trainer::Fault::fromKey(key.toStdString(), &k) ? f
                              : drive.isEmpty()                                ? trainer::Fault::label(k)
                                                                               : tr("%1 (%2)").arg(trainer::Fault::label(k), drive);
        QAction* a = m_clearMenu->addAction(label);
        a->setData(f);
        connect(a, &QAction::triggered, this, [this, key, drive] { sendCommand("clear", key, drive); });
    }
}

}  // namespace studio
