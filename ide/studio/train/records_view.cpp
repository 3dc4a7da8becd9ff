#include "ide/studio/train/records_view.h"

#include "ide/i18n/language.h"
#include "trainer/training/session.h"
#include "trainer/training/tutorial.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QLineEdit>
#include <QLineSeries>
#include <QListWidget>
#include <QLocale>
#include <QMessageBox>
#include <QPen>
#include <QPushButton>
#include <QScatterSeries>
#include <QSettings>
#include <QSplitter>
#include <QStandardPaths>
#include <QTableWidget>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace studio {

namespace {

namespace rec = trainer::records;

/// The pass marks' colour in the chart (no attempt series has it).
constexpr QRgb kPassMarkColour = 0xff2e9d4a;

QString num(double v, int decimals) { return QLocale().toString(v, 'f', decimals); }

QString when(const QDateTime& utc)
{
    if (!utc.isValid()) return QStringLiteral("—");
    // the locale's short form, with the year's four digits (28/11/2026 16:30, not 28/11/26)
    QString format = QLocale().dateTimeFormat(QLocale::ShortFormat);
    if (!format.contains(QLatin1String("yyyy"))) format.replace(QLatin1String("yy"), QLatin1String("yyyy"));
    return QLocale().toString(utc.toLocalTime(), format);
}

QString statusText(rec::AttemptStatus s)
{
    switch (s) {
    case rec::AttemptStatus::Running: return RecordsView::tr("running");
    case rec::AttemptStatus::Finished: return RecordsView::tr("finished");
    case rec::AttemptStatus::Aborted: return RecordsView::tr("stopped");
    case rec::AttemptStatus::Interrupted: return RecordsView::tr("interrupted");
    }
    return {};
}

QTableWidget* table(int columns)
{
    auto* t = new QTableWidget(0, columns);
    t->verticalHeader()->hide();
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setSelectionBehavior(QAbstractItemView::SelectRows);
    t->setSelectionMode(QAbstractItemView::SingleSelection);
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->horizontalHeader()->setStretchLastSection(true);
    return t;
}

QTableWidgetItem* cell(const QString& text, bool number = false)
{
    auto* it = new QTableWidgetItem(text);
    if (number) it->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return it;
}

}  // namespace

RecordsView::RecordsView(QWidget* parent) : QWidget(parent)
{
    setObjectName("RecordsView");
    // a trainer's desk view: smaller than the trainee's screens (the page's 14 pt)
    setStyleSheet("QTableWidget, QListWidget, QLineEdit, QHeaderView, QHeaderView::section { font-size: 11pt; }");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(16, 12, 16, 12);
    auto* title = new QLabel;
    title->setObjectName("TrainTitle");
    layout->addWidget(title);
    m_message = new QLabel;
    m_message->setObjectName("RecordsMessage");
    m_message->setWordWrap(true);
    m_message->setStyleSheet("color: #b35c00;");
    m_message->hide();
    layout->addWidget(m_message);

    auto* split = new QSplitter(Qt::Horizontal);
    // the operators and adding one
    auto* left = new QWidget;
    auto* leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    auto* operatorsTitle = new QLabel;
    leftLayout->addWidget(operatorsTitle);
    m_operators = table(5);
    m_operators->setObjectName("RecordsOperators");
    leftLayout->addWidget(m_operators, 1);
    auto* addRow = new QHBoxLayout;
    auto* addFields = new QHBoxLayout;
    m_newCode = new QLineEdit;
    m_newCode->setMinimumWidth(110);
    m_newCode->setObjectName("NewOperatorCode");
    m_newName = new QLineEdit;
    m_newName->setObjectName("NewOperatorName");
    m_add = new QPushButton;
    m_add->setObjectName("AddOperatorButton");
    m_newName->setMinimumWidth(180);
    addFields->addWidget(m_newCode, 1);
    addFields->addWidget(m_newName, 2);
    addRow->addStretch();
    addRow->addWidget(m_add);
    leftLayout->addLayout(addFields);
    leftLayout->addLayout(addRow);
    left->setMinimumWidth(520);
    split->addWidget(left);

    // the selected operator: attempts, the selected one's breakdown and events, the chart
    auto* right = new QSplitter(Qt::Vertical);
    auto* top = new QWidget;
    auto* topLayout = new QHBoxLayout(top);
    topLayout->setContentsMargins(0, 0, 0, 0);
    auto* attemptsBox = new QVBoxLayout;
    auto* attemptsTitle = new QLabel;
    attemptsBox->addWidget(attemptsTitle);
    m_attempts = table(5);
    m_attempts->setObjectName("RecordsAttempts");
    m_attempts->horizontalHeader()->setStretchLastSection(false);
    // the tutorial takes what is left (elided, in full as a tooltip): the rest stays whole
    m_attempts->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    attemptsBox->addWidget(m_attempts, 1);
    topLayout->addLayout(attemptsBox, 2);
    auto* detail = new QVBoxLayout;
    auto* breakdownTitle = new QLabel;
    detail->addWidget(breakdownTitle);
    m_breakdown = table(4);
    m_breakdown->setObjectName("RecordsBreakdown");
    m_breakdown->setSelectionMode(QAbstractItemView::NoSelection);
    m_breakdown->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_breakdown->horizontalHeader()->setStretchLastSection(false);
    detail->addWidget(m_breakdown, 1);
    auto* eventsTitle = new QLabel;
    detail->addWidget(eventsTitle);
    m_events = new QListWidget;
    m_events->setObjectName("RecordsEvents");
    m_events->setWordWrap(true);
    detail->addWidget(m_events, 1);
    topLayout->addLayout(detail, 1);
    right->addWidget(top);
    m_chart = new QChartView;
    m_chart->setObjectName("RecordsChart");
    m_chart->setRenderHint(QPainter::Antialiasing);
    m_chart->setMinimumHeight(220);
    right->addWidget(m_chart);
    right->setStretchFactor(0, 3);
    right->setStretchFactor(1, 2);
    split->addWidget(right);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 4);
    split->setSizes({520, 1140});  // the attempts' columns visible (Spanish too)
    layout->addWidget(split, 1);

    auto* buttons = new QHBoxLayout;
    auto* back = new QPushButton;
    back->setObjectName("RecordsBack");
    auto* reload = new QPushButton;
    m_export = new QPushButton;
    m_export->setObjectName("ExportCsvButton");
    m_texts.add([=, this] {
        title->setText(tr("Trainee records"));
        operatorsTitle->setText("<b>" + tr("Operators") + "</b>");
        m_operators->setHorizontalHeaderLabels({tr("Code"), tr("Name"), tr("Attempts"), tr("Passed"), tr("Last attempt")});
        m_newCode->setPlaceholderText(tr("code"));
        m_newName->setPlaceholderText(tr("name"));
        m_add->setText(tr("Add operator"));
        attemptsTitle->setText("<b>" + tr("Attempts (newest first)") + "</b>");
        m_attempts->setHorizontalHeaderLabels(
            {tr("Started"), tr("Tutorial"), tr("Status"), tr("Score"), tr("Time [s]")});
        breakdownTitle->setText("<b>" + tr("Breakdown") + "</b>");
        m_breakdown->setHorizontalHeaderLabels({tr("Measure"), tr("Value"), tr("Points"), tr("Of")});
        eventsTitle->setText("<b>" + tr("Events") + "</b>");
        back->setText(tr("Back to the course"));
        reload->setText(tr("Refresh"));
        m_export->setText(tr("Export CSV…"));
    });
    // the trainer's choice for Trainer Mode (kiosk): whether trainees may watch the expert
    m_kioskExpert = new QCheckBox;
    m_kioskExpert->setObjectName("KioskShowExpert");
    m_kioskExpert->setChecked(QSettings().value("trainer/kioskShowExpert", false).toBool());
    connect(m_kioskExpert, &QCheckBox::toggled, this, [](bool on) { QSettings().setValue("trainer/kioskShowExpert", on); });
    m_exported = new QLabel;
    m_exported->setObjectName("ExportStatus");
    m_exported->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_exported->hide();
    m_texts.add([this] {
        m_kioskExpert->setText(tr("Trainees see the expert in Trainer Mode"));
        m_kioskExpert->setToolTip(tr("In Trainer Mode the trainee cannot change this: the expert's translucent "
                                     "machine runs beside each attempt only when it is on."));
        m_exported->clear();
        m_exported->hide();
    });
    buttons->addWidget(back);
    buttons->addSpacing(12);
    buttons->addWidget(m_kioskExpert);
    buttons->addStretch();
    buttons->addWidget(m_exported);
    buttons->addWidget(reload);
    buttons->addWidget(m_export);
    layout->addLayout(buttons);

    connect(back, &QPushButton::clicked, this, &RecordsView::backRequested);
    connect(reload, &QPushButton::clicked, this, &RecordsView::refresh);
    connect(m_operators, &QTableWidget::currentCellChanged, this, [this](int row) { showOperator(row); });
    connect(m_attempts, &QTableWidget::currentCellChanged, this, [this](int row) { showAttempt(row); });
    const auto add = [this] {
        QString error;
        if (addOperator(m_newCode->text(), m_newName->text(), &error)) {
            m_newCode->clear();
            m_newName->clear();
        } else {
            QMessageBox::warning(this, tr("Add operator"), error);
        }
    };
    connect(m_add, &QPushButton::clicked, this, add);
    connect(m_newName, &QLineEdit::returnPressed, this, add);
    connect(m_export, &QPushButton::clicked, this, [this] {
        const QString dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
        const QString path = QFileDialog::getSaveFileName(this, tr("Export CSV"), dir + "/padrob-attempts.csv",
                                                          tr("CSV files (*.csv);;All files (*)"));
        if (path.isEmpty()) return;
        QString error;
        if (!exportCsv(path, &error)) QMessageBox::warning(this, tr("Export CSV"), error);
    });
    setRecords(nullptr, {});
}

void RecordsView::setRecords(trainer::records::RecordsDb* db, const QString& problem)
{
    m_db = db;
    m_problem = problem;
    refresh();
}

void RecordsView::setTutorials(const QHash<QString, QString>& titles, const QHash<QString, double>& passMarks,
                               const QHash<QString, std::shared_ptr<const trainer::Tutorial>>& tutorials)
{
    m_titles = titles;
    m_passMarks = passMarks;
    m_tutorials = tutorials;
}

void RecordsView::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        m_texts.apply();
        const int attempt = m_attempts->currentRow();
        refresh();  // keeps the operator
        if (attempt >= 0 && attempt < m_attempts->rowCount()) m_attempts->setCurrentCell(attempt, 0);
    }
    QWidget::changeEvent(event);
}

QString RecordsView::titleOf(const rec::Attempt& a) const
{
    const QString title = m_titles.value(a.tutorialId, a.tutorialTitle);
    return title.isEmpty() ? a.tutorialId : a.tutorialId + " " + title;
}

QString RecordsView::eventText(const rec::Attempt& a, const rec::AttemptEvent& e) const
{
    // as the trainee read it, unless that was in another language: worded again from its kind
    if (a.language == i18n::current()) return e.text;
    using Kind = trainer::TutorialEvent::Kind;
    trainer::TutorialEvent event;
    bool known = false;
    for (int k = 0; k <= int(Kind::Aborted) && !known; ++k) {
        if (e.kind == QLatin1String(trainer::TutorialEvent::key(Kind(k)))) {
            event.kind = Kind(k);
            known = true;
        }
    }
    if (!known) return e.text;
    event.t = e.t;
    event.value = std::isnan(e.value) ? 0.0 : e.value;
    event.penalty = e.penalty;
    event.detail = e.detail.toStdString();
    // a part or a person is kept by its English name: the tutorial names it in the language
    const trainer::Tutorial* t = m_tutorials.value(a.tutorialId).get();
    if (t) {
        const bool worker = event.kind == Kind::WorkerZone || event.kind == Kind::WorkerHit;
        if (worker) {
            for (std::size_t i = 0; i < t->spec.workers.size(); ++i)
                if (t->spec.workers[i].name.in("en") == event.detail) event.subject = int(i);
        } else {
            for (std::size_t i = 0; i < t->spec.parts.size(); ++i)
                if (t->spec.parts[i].name.in("en") == event.detail) event.subject = int(i);
        }
    }
    return event.text(t, i18n::current().toStdString());
}

void RecordsView::refresh()
{
    const int oldRow = m_operators->currentRow();
    const QString selected = oldRow >= 0 && oldRow < m_progress.size() ? m_progress[oldRow].op.code : QString();
    m_progress.clear();
    QString error;
    if (!m_db) error = m_problem.isEmpty() ? tr("There are no trainee records.") : m_problem;
    else if (!m_db->progress(m_progress, &error)) m_progress.clear();
    if (!error.isEmpty())
        error = tr("The trainee records cannot be read: %1 Training goes on; attempts are kept in pending files and "
                   "added to the records the next time they open.").arg(error);
    else if (m_db && m_db->isReadOnly())
        error = tr("The trainee records are open read-only: %1").arg(m_db->where());
    m_message->setText(error);
    m_message->setVisible(!error.isEmpty());
    const bool writable = m_db && !m_db->isReadOnly();
    m_add->setEnabled(writable);
    m_newCode->setEnabled(writable);
    m_newName->setEnabled(writable);
    m_export->setEnabled(m_db != nullptr);

    const QSignalBlocker block(m_operators);
    m_operators->setRowCount(int(m_progress.size()));
    int select = m_progress.isEmpty() ? -1 : 0;
    for (int i = 0; i < m_progress.size(); ++i) {
        const rec::OperatorProgress& p = m_progress[i];
        m_operators->setItem(i, 0, cell(p.op.code));
        // the guest, made by Padrob, is named in the current language
        m_operators->setItem(i, 1, cell(p.op.code == QLatin1String("guest") ? tr("Guest") : p.op.name));
        m_operators->setItem(i, 2, cell(QLocale().toString(p.attempts), true));
        m_operators->setItem(i, 3, cell(QLocale().toString(p.tutorialsPassed), true));
        m_operators->setItem(i, 4, cell(when(p.lastAttempt)));
        if (p.op.code == selected) select = i;
    }
    m_operators->setCurrentCell(select, 0);
    showOperator(select);
}

bool RecordsView::selectOperator(const QString& code)
{
    for (int i = 0; i < m_progress.size(); ++i) {
        if (m_progress[i].op.code != code) continue;
        m_operators->setCurrentCell(i, 0);  // shows it
        return true;
    }
    return false;
}

void RecordsView::showOperator(int row)
{
    m_list.clear();
    const QSignalBlocker block(m_attempts);
    if (m_db && row >= 0 && row < m_progress.size()) m_db->attemptsOf(m_progress[row].op.id, m_list, true);
    m_attempts->setRowCount(int(m_list.size()));
    for (int i = 0; i < m_list.size(); ++i) {
        const rec::Attempt& a = m_list[i];
        const bool scored = rec::hasScore(a.status);
        // a finished attempt by its outcome (the column stays narrow enough for Spanish)
        QString status = statusText(a.status);
        if (a.status == rec::AttemptStatus::Finished) status = a.passed ? tr("passed") : tr("not passed");
        m_attempts->setItem(i, 0, cell(when(a.started)));
        m_attempts->setItem(i, 1, cell(titleOf(a)));
        m_attempts->item(i, 1)->setToolTip(titleOf(a));
        m_attempts->setItem(i, 2, cell(status));
        // the score and its stars in one cell ("91 ★★☆"; the numbers stay aligned)
        QString stars;
        for (int k = 0; k < 3; ++k) stars += k < a.stars ? QChar(0x2605) : QChar(0x2606);
        m_attempts->setItem(i, 3, cell(scored ? num(a.score, 0) + QLatin1Char(' ') + stars : QString(), true));
        m_attempts->setItem(i, 4, cell(scored ? num(a.durationS, 1) : QString(), true));
    }
    m_attempts->setCurrentCell(m_list.isEmpty() ? -1 : 0, 0);
    showAttempt(m_list.isEmpty() ? -1 : 0);
    fillChart(m_list);
}

void RecordsView::showAttempt(int row)
{
    m_breakdown->setRowCount(0);
    m_events->clear();
    if (row < 0 || row >= m_list.size()) return;
    const rec::Attempt& a = m_list[row];
    m_breakdown->setRowCount(int(a.breakdown.size()));
    for (int i = 0; i < a.breakdown.size(); ++i) {
        const rec::ScoreItem& s = a.breakdown[i];
        // the criterion's name in the current language when it is one Padrob knows
        trainer::ScoreItem known;
        known.key = s.key.toStdString();
        const QString label = known.label() != s.key ? known.label() : s.label.isEmpty() ? s.key : s.label;
        m_breakdown->setItem(i, 0, cell(label));
        m_breakdown->setItem(i, 1, cell(num(s.value, 2), true));
        m_breakdown->setItem(i, 2, cell(num(s.points, 1), true));
        m_breakdown->setItem(i, 3, cell(s.maxPoints > 0 ? num(s.maxPoints, 0) : QString(), true));
    }
    for (const rec::AttemptEvent& e : a.events) {
        QString text = tr("%1 s — %2").arg(num(e.t, 1), eventText(a, e));
        if (e.penalty > 0) text += " " + tr("(−%1)").arg(num(e.penalty, 0));
        m_events->addItem(text);
    }
    if (a.events.isEmpty()) m_events->addItem(tr("No events."));
}

void RecordsView::fillChart(const QList<trainer::records::Attempt>& attempts)
{
    auto* chart = new QChart;
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->setLocalizeNumbers(true);
    chart->setLocale(QLocale());
    chart->setTitle(tr("Score of each attempt"));
    chart->setMargins(QMargins(4, 4, 4, 4));
    auto* x = new QValueAxis;
    x->setTitleText(tr("attempt"));
    x->setLabelFormat("%.0f");  // (QtCharts' localized labels take only 'f' formats)
    auto* y = new QValueAxis;
    y->setTitleText(tr("score"));
    y->setRange(0, 100);
    y->setLabelFormat("%.0f");
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    // the operator's attempts oldest first, numbered; one series per tutorial
    QMap<QString, QLineSeries*> byTutorial;
    const int n = int(attempts.size());
    for (int k = n - 1; k >= 0; --k) {
        const rec::Attempt& a = attempts[k];
        if (!rec::hasScore(a.status)) continue;
        QLineSeries*& s = byTutorial[a.tutorialId];
        if (!s) {
            s = new QLineSeries;
            s->setName(titleOf(a));
            s->setPointsVisible(true);
        }
        s->append(n - k, a.score);
    }
    const double xMax = std::max(2, n);
    // the attempts in colours that are never the pass mark's (green)
    const QColor attemptColours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e), QColor(0x94, 0x67, 0xbd),
                                     QColor(0x8c, 0x56, 0x4b), QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf),
                                     QColor(0x7f, 0x7f, 0x7f), QColor(0xd6, 0x27, 0x28)};
    int colour = 0;
    for (QLineSeries* s : byTutorial) {
        chart->addSeries(s);
        s->setColor(attemptColours[colour++ % std::size(attemptColours)]);
        s->attachAxis(x);
        s->attachAxis(y);
    }
    // each tutorial's pass mark: a dashed green line, named with its tutorials
    QMap<double, QStringList> marks;
    for (auto it = byTutorial.begin(); it != byTutorial.end(); ++it)
        if (m_passMarks.contains(it.key())) marks[m_passMarks.value(it.key())] << it.key();
    for (auto it = marks.begin(); it != marks.end(); ++it) {
        auto* line = new QLineSeries;
        line->setName(tr("pass mark %1 (%2)").arg(num(it.key(), 0), it.value().join(", ")));
        line->append(1, it.key());
        line->append(xMax, it.key());
        line->setObjectName("PassMark");
        QPen pen{QColor(kPassMarkColour)};
        pen.setStyle(Qt::DashLine);
        pen.setWidth(2);
        chart->addSeries(line);
        line->setPen(pen);
        line->attachAxis(x);
        line->attachAxis(y);
    }
    x->setRange(1, xMax);
    x->setTickCount(int(std::min(xMax, 11.0)));
    chart->legend()->setVisible(!byTutorial.isEmpty());
    chart->legend()->setAlignment(Qt::AlignRight);
    QChart* old = m_chart->chart();
    m_chart->setChart(chart);
    delete old;
}

bool RecordsView::addOperator(const QString& code, const QString& name, QString* error)
{
    if (!m_db) {
        if (error) *error = m_problem.isEmpty() ? tr("There are no trainee records.") : m_problem;
        return false;
    }
    if (code.trimmed().isEmpty()) {
        if (error) *error = tr("Type the operator's code (badge number…).");
        return false;
    }
    if (m_db->addOperator(code, name.trimmed().isEmpty() ? code.trimmed() : name.trimmed(), error) == 0) return false;
    refresh();
    selectOperator(code.trimmed());
    emit operatorsChanged();
    return true;
}

bool RecordsView::exportCsv(const QString& path, QString* error)
{
    if (!m_db) {
        if (error) *error = m_problem.isEmpty() ? tr("There are no trainee records.") : m_problem;
        return false;
    }
    int rows = 0;
    if (!m_db->exportCsv(path, error, m_titles, &rows)) return false;
    m_exported->setText(tr("Wrote %n attempt(s) to %1.", nullptr, rows).arg(QDir::toNativeSeparators(path)));
    m_exported->show();
    return true;
}

}  // namespace studio
