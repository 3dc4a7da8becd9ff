#include "ide/studio/station/station_page.h"

#include "ide/studio/station/calibration_wizard.h"
#include "ide/studio/station/channel_bars.h"
#include "ide/studio/station/live_state.h"
#include "ide/studio/station/mapping_table.h"
#include "ide/studio/station/serial_console_dialog.h"
#include "trainer/input/input_log.h"

#include <QComboBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QPointer>
#include <QFrame>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSplitter>
#include <QStandardItemModel>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace studio {

namespace {

QString issuesKey(const QList<trainer::ProfileIssue>& issues)
{
    QString key;
    for (const trainer::ProfileIssue& i : issues) key += i.text() + QLatin1Char(i.error ? 'E' : 'W') + QLatin1Char('\n');
    return key;
}

}  // namespace

StationPage::StationPage(trainer::Station* station, QWidget* parent) : QWidget(parent), m_station(station)
{
    auto* layout = new QVBoxLayout(this);
    buildProfileBar(layout);

    // the banner: active bank and warnings
    m_banner = new QFrame(this);
    m_banner->setObjectName(QStringLiteral("stationBanner"));
    auto* bannerLayout = new QHBoxLayout(m_banner);
    bannerLayout->setContentsMargins(12, 6, 12, 6);
    m_bank = new QLabel(m_banner);
    QFont big = m_bank->font();
    big.setPointSizeF(big.pointSizeF() * 1.45);
    big.setBold(true);
    m_bank->setFont(big);
    m_texts.add([this] { m_bank->setToolTip(tr("The bank of mappings the operator's levers drive now")); });
    bannerLayout->addWidget(m_bank, 0, Qt::AlignTop);
    bannerLayout->addSpacing(24);
    m_warnings = new QLabel(m_banner);
    m_warnings->setWordWrap(true);
    m_warnings->setTextFormat(Qt::PlainText);
    m_warnings->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont warningFont = m_warnings->font();
    warningFont.setBold(true);
    m_warnings->setFont(warningFont);
    bannerLayout->addWidget(m_warnings, 1);
    layout->addWidget(m_banner);

    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->setChildrenCollapsible(false);
    splitter->addWidget(buildDevices(splitter));
    auto* mapping = new QGroupBox(splitter);
    m_texts.add([mapping] { mapping->setTitle(tr("Valve mapping")); });
    auto* mappingLayout = new QVBoxLayout(mapping);
    m_mappings = new MappingTable(mapping);
    mappingLayout->addWidget(m_mappings);
    splitter->addWidget(mapping);
    splitter->setStretchFactor(0, 5);
    splitter->setStretchFactor(1, 6);
    splitter->setSizes({620, 880});  // the devices' status readable in Spanish too
    layout->addWidget(splitter, 1);

    m_mappings->setConfirm([this](const QString& question) { return ask(tr("Remove bank"), question); });
    connect(m_mappings, &MappingTable::edited, this, &StationPage::mappingEdited);
    connect(m_channels, &ChannelPanel::calibrateRequested, this, [this](int axis) { calibrate(axis); });
    connect(m_channels, &ChannelPanel::rampChanged, this, &StationPage::setKeyRamp);

    m_timer = new QTimer(this);
    m_timer->setInterval(1000 / kRefreshHz);
    connect(m_timer, &QTimer::timeout, this, &StationPage::refresh);
    showBanner(trainer::StationState{});
    updateButtons();
}

StationPage::~StationPage()
{
    // the recorder is used in the input thread: detach it there before it goes
    if (m_recorder && m_station) {
        trainer::InputRecorder* r = m_recorder.get();
        m_station->call([r](trainer::StationEngine& e) {
            e.setRecorder(nullptr);
            r->stop();
        });
    }
    if (isReplaying() && m_station) {
        auto devices = std::move(m_replays);
        m_station->post([devices](trainer::StationEngine& e) {
            for (const auto& d : devices) e.removeDevice(d.get());
            e.setReplayOnly(false);
        });
    }
}

void StationPage::buildProfileBar(QVBoxLayout* layout)
{
    auto* bar = new QHBoxLayout;
    auto* title = new QLabel(this);
    QFont bold = title->font();
    bold.setBold(true);
    title->setFont(bold);
    bar->addWidget(title);
    m_profiles = new QComboBox(this);
    m_profiles->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_profiles->setMinimumContentsLength(30);
    connect(m_profiles, &QComboBox::activated, this, &StationPage::profileActivated);
    bar->addWidget(m_profiles);
    m_new = new QPushButton(this);
    m_save = new QPushButton(this);
    m_saveAs = new QPushButton(this);
    m_delete = new QPushButton(this);
    m_import = new QPushButton(this);
    m_export = new QPushButton(this);
    m_texts.add([this, title] {
        title->setText(tr("Profile:"));
        m_profiles->setToolTip(tr("The station profiles of this model: yours, and those shipped with it"));
        m_new->setText(tr("New"));
        m_new->setToolTip(tr("An empty profile with one bank"));
        m_save->setText(tr("Save"));
        m_save->setToolTip(tr("Save the profile under its name (a shipped profile is saved as your own copy)"));
        m_saveAs->setText(tr("Save As…"));
        m_delete->setText(tr("Delete"));
        m_delete->setToolTip(tr("Delete this profile of yours (shipped profiles cannot be deleted)"));
        m_import->setText(tr("Import…"));
        m_import->setToolTip(tr("Add a profile file (from another station) to this model's profiles"));
        m_export->setText(tr("Export…"));
        m_export->setToolTip(tr("Write this profile to a file"));
    });
    for (QPushButton* b : {m_new, m_save, m_saveAs, m_delete, m_import, m_export}) bar->addWidget(b);
    bar->addStretch(1);
    connect(m_new, &QPushButton::clicked, this, [this] { newProfile(); });
    connect(m_save, &QPushButton::clicked, this, [this] { save(); });
    connect(m_saveAs, &QPushButton::clicked, this, [this] { saveAs(); });
    connect(m_delete, &QPushButton::clicked, this, [this] { deleteProfile(); });
    connect(m_import, &QPushButton::clicked, this, [this] { importProfile(); });
    connect(m_export, &QPushButton::clicked, this, [this] { exportProfile(); });
    layout->addLayout(bar);

    m_description = new QLabel(this);
    m_description->setWordWrap(true);
    m_description->setStyleSheet(QStringLiteral("color: palette(placeholder-text)"));
    m_description->hide();
    layout->addWidget(m_description);

    m_error = new QLabel(this);
    m_error->setWordWrap(true);
    m_error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_error->setStyleSheet(QStringLiteral("color: %1").arg(redColor().name()));
    m_error->hide();
    layout->addWidget(m_error);

    m_issues = new QListWidget(this);
    m_issues->setSelectionMode(QAbstractItemView::NoSelection);
    m_issues->setFocusPolicy(Qt::NoFocus);
    m_texts.add([this] {
        m_issues->setToolTip(tr("Problems of this profile with this model: a mapping with a warning is ignored"));
    });
    m_issues->hide();
    layout->addWidget(m_issues);
}

QWidget* StationPage::buildDevices(QWidget* parent)
{
    auto* left = new QWidget(parent);
    auto* layout = new QVBoxLayout(left);
    layout->setContentsMargins(0, 0, 0, 0);

    auto* devices = new QGroupBox(left);
    auto* dl = new QVBoxLayout(devices);
    m_devices = new QTreeWidget(devices);
    m_devices->setColumnCount(DeviceColumnCount);
    m_texts.add([this, devices] {
        devices->setTitle(tr("Devices"));
        m_devices->setHeaderLabels({tr("Device"), tr("Status"), tr("Samples"), tr("Dropped")});
        m_devices->headerItem()->setToolTip(DroppedColumn,
                                            tr("Readings dropped as corrupt (a serial line with a bad checksum…)"));
    });
    m_devices->setRootIsDecorated(false);
    m_devices->setAllColumnsShowFocus(true);
    m_devices->setTextElideMode(Qt::ElideMiddle);
    QHeaderView* header = m_devices->header();
    header->setStretchLastSection(false);
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->setSectionResizeMode(StatusColumn, QHeaderView::Stretch);
    m_devices->setColumnWidth(NameColumn, 210);
    // "Muestras", "Descartadas": the headers' width in any language
    header->setSectionResizeMode(SamplesColumn, QHeaderView::ResizeToContents);
    header->setSectionResizeMode(DroppedColumn, QHeaderView::ResizeToContents);
    const int lineHeight = m_devices->fontMetrics().height();
    m_devices->setMinimumHeight(5 * lineHeight);
    m_devices->setMaximumHeight(10 * lineHeight);
    dl->addWidget(m_devices);
    m_deviceDetail = new QLabel(devices);
    m_deviceDetail->setWordWrap(true);
    m_deviceDetail->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_deviceDetail->hide();
    dl->addWidget(m_deviceDetail);
    connect(m_devices, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (!item) return;
        selectDevice(item->data(NameColumn, kNameRole).toString(), item->data(NameColumn, kReplayRole).toBool());
    });

    auto* buttons = new QHBoxLayout;
    m_addSerial = new QPushButton(devices);
    m_removeDevice = new QPushButton(devices);
    m_record = new QPushButton(tr("Record input…"), devices);
    m_replay = new QPushButton(tr("Replay a log…"), devices);
    m_texts.add([this] {  // (the record and replay buttons' texts: updateButtons())
        m_addSerial->setText(tr("Add serial console…"));
        m_addSerial->setToolTip(tr("A replica console (DAQ box) on a serial port, kept in the profile"));
        m_removeDevice->setText(tr("Remove"));
        m_removeDevice->setToolTip(tr("Remove the selected device from the profile (only devices the profile opens: "
                                      "joysticks and gamepads are found by themselves)"));
        m_record->setToolTip(tr("Write everything the devices read to an input log"));
        m_replay->setToolTip(tr("Play a recorded input log: it drives the machine instead of the operator"));
    });
    connect(m_addSerial, &QPushButton::clicked, this, [this] { addSerialConsole(); });
    connect(m_removeDevice, &QPushButton::clicked, this, [this] { removeSelectedDevice(); });
    connect(m_record, &QPushButton::clicked, this, [this] { isRecording() ? stopRecording() : startRecording(); });
    connect(m_replay, &QPushButton::clicked, this, [this] {
        if (isReplaying()) stopReplay();
        else startReplay();
    });
    // two rows of two: one row of four is wider than the devices' side at 1280×720 in Spanish
    auto* moreButtons = new QHBoxLayout;
    buttons->addWidget(m_addSerial);
    buttons->addWidget(m_removeDevice);
    buttons->addStretch(1);
    moreButtons->addWidget(m_record);
    moreButtons->addWidget(m_replay);
    moreButtons->addStretch(1);
    dl->addLayout(buttons);
    dl->addLayout(moreButtons);
    m_activity = new QLabel(devices);
    m_activity->setWordWrap(true);
    m_activity->hide();
    dl->addWidget(m_activity);
    layout->addWidget(devices, 0);

    auto* channels = new QGroupBox(left);
    m_texts.add([channels] { channels->setTitle(tr("Channels")); });
    auto* cl = new QVBoxLayout(channels);
    auto* scroll = new QScrollArea(channels);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_channels = new ChannelPanel(scroll);
    scroll->setWidget(m_channels);
    cl->addWidget(scroll);
    layout->addWidget(channels, 1);
    return left;
}

// ---- model and store -----------------------------------------------------------

void StationPage::setProfileStore(const trainer::ProfileStore& store)
{
    m_doc.setStore(store);
    m_doc.relist();
    fillCombo();
}

void StationPage::setDrives(const QList<trainer::DriveInfo>& drives)
{
    m_drives = drives;
    m_mappings->setDrives(drives);
    m_mappings->setProfile(m_doc.profile());
    install(true);
}

void StationPage::setModel(const QString& modelPath, const QList<trainer::DriveInfo>& drives, const QString& preferred)
{
    m_drives = drives;
    m_mappings->setDrives(drives);
    const bool was = m_doc.isDirty();
    m_doc.setModelPath(modelPath);
    clearError();
    // the preferred profile, the first readable one, or the model's default
    m_doc.openFirst(preferred, drives);
    showCurrent(was);
}

void StationPage::fillCombo()
{
    const QSignalBlocker block(m_profiles);
    m_profiles->clear();
    auto* model = qobject_cast<QStandardItemModel*>(m_profiles->model());
    const QString star = m_doc.isDirty() ? QStringLiteral(" *") : QString();
    const trainer::StationProfile& profile = m_doc.profile();
    const bool unsaved = m_doc.origin() == ProfileDocument::Origin::Unsaved;
    int current = -1;
    if (unsaved) {
        const QString name = profile.name.isEmpty() ? tr("(no name)") : profile.name;
        m_profiles->addItem(tr("%1 (not saved)").arg(name) + star);
        m_profiles->setItemData(0, profile.name, kNameRole);
        m_profiles->setItemData(0, false, kStoredRole);
        m_profiles->setItemData(0, tr("This profile is not saved yet"), Qt::ToolTipRole);
        current = 0;
    }
    for (const trainer::StoredProfile& s : m_doc.stored()) {
        QString text = s.label;
        if (!s.readable) text = tr("%1 (unreadable)").arg(s.label);
        else if (s.shipped) text = tr("%1 (shipped)").arg(s.label);
        const bool isCurrent = !unsaved && s.readable && s.name == m_doc.storedName();
        if (isCurrent) text += star;
        const int i = m_profiles->count();
        m_profiles->addItem(text);
        m_profiles->setItemData(i, s.name, kNameRole);
        m_profiles->setItemData(i, true, kStoredRole);
        m_profiles->setItemData(i, s.readable ? s.path : s.problem, Qt::ToolTipRole);
        if (!s.readable && model) {
            model->item(i)->setEnabled(false);
            model->item(i)->setForeground(redColor());
        }
        if (isCurrent) current = i;
    }
    m_profiles->setCurrentIndex(current);
}

void StationPage::profileActivated(int index)
{
    if (index < 0 || !m_profiles->itemData(index, kStoredRole).toBool()) return;
    const QString name = m_profiles->itemData(index, kNameRole).toString();
    if (m_doc.origin() != ProfileDocument::Origin::Unsaved && name == m_doc.storedName() && !m_doc.isDirty()) return;
    if (!loadProfile(name)) fillCombo();
}

// ---- the profile ---------------------------------------------------------------

void StationPage::showCurrent(bool wasDirty)
{
    const trainer::StationProfile& profile = m_doc.profile();
    m_mappings->setProfile(profile);
    m_description->setText(profile.localized(profile.description));
    m_description->setVisible(!profile.description.isEmpty());
    fillCombo();
    if (wasDirty != m_doc.isDirty()) emit dirtyChanged(m_doc.isDirty());
    updateButtons();
    install(false);
}

void StationPage::setDirty(bool dirty)
{
    if (!m_doc.setDirty(dirty)) return;
    fillCombo();
    updateButtons();
    emit dirtyChanged(dirty);
}

void StationPage::install(bool keepBank)
{
    const trainer::StationProfile p = m_doc.profile();
    const int bank = keepBank && m_state ? m_state->activeBank : 0;
    if (m_station)
        m_station->post([p, bank](trainer::StationEngine& e) {
            e.setProfile(p);
            if (bank > 0) e.selectBank(bank);
        });
    emit profileChanged(m_doc.profile());
    refresh();
}

bool StationPage::maybeDiscard()
{
    if (!m_doc.isDirty()) return true;
    return ask(tr("Unsaved changes"),
               tr("The profile “%1” has changes that are not saved. Discard them?").arg(m_doc.profile().name));
}

QString StationPage::lastError() const
{
    return m_error->text();
}

void StationPage::showError(const QString& text)
{
    m_error->setText(text);
    m_error->setVisible(!text.isEmpty());
}

void StationPage::clearError()
{
    showError({});
}

bool StationPage::loadProfile(const QString& name)
{
    if (!maybeDiscard()) return false;
    return loadStored(name);
}

bool StationPage::loadStored(const QString& name)
{
    const bool was = m_doc.isDirty();
    QString error;
    if (!m_doc.open(name, &error)) {
        showError(error);
        fillCombo();
        return false;
    }
    clearError();
    showCurrent(was);
    return true;
}

bool StationPage::newProfile(const QString& nameIn)
{
    if (!maybeDiscard()) return false;
    QString name = nameIn.trimmed();
    if (name.isEmpty()) name = askText(tr("New profile"), tr("Name of the new profile:"), tr("New profile")).trimmed();
    if (name.isEmpty()) return false;
    const bool was = m_doc.isDirty();
    m_doc.makeNew(name, tr("Bank 1"));
    clearError();
    showCurrent(was);
    return true;
}

bool StationPage::save()
{
    return saveUnder(m_doc.profile().name, m_doc.saveMustAsk());
}

bool StationPage::saveAs(const QString& nameIn)
{
    QString name = nameIn.trimmed();
    if (name.isEmpty()) name = askText(tr("Save profile as"), tr("Name of the profile:"), m_doc.profile().name).trimmed();
    if (name.isEmpty()) return false;
    return saveUnder(name, true);
}

bool StationPage::saveUnder(const QString& nameIn, bool askBeforeReplacing)
{
    const QString name = nameIn.trimmed();
    if (name.isEmpty()) {
        showError(tr("A profile needs a name."));
        return false;
    }
    const bool replacing = m_doc.exists(name);
    if (replacing && askBeforeReplacing &&
        !ask(tr("Replace profile"), tr("A profile named “%1” exists already for this model. Replace it?").arg(name)))
        return false;
    QString error;
    if (!m_doc.saveUnder(name, replacing, &error)) {
        showError(tr("Cannot save the profile: %1").arg(error));
        tell(tr("Save profile"), error);
        return false;
    }
    clearError();
    if (m_doc.isDirty()) {
        setDirty(false);
    } else {
        fillCombo();
        updateButtons();
    }
    emit profileChanged(m_doc.profile());
    return true;
}

bool StationPage::deleteProfile()
{
    if (m_doc.origin() != ProfileDocument::Origin::User) return false;
    const QString name = m_doc.storedName();
    if (!ask(tr("Delete profile"), tr("Delete the profile “%1”? This cannot be undone.").arg(name))) return false;
    QString error;
    if (!m_doc.remove(&error)) {
        showError(tr("Cannot delete the profile: %1").arg(error));
        tell(tr("Delete profile"), error);
        return false;
    }
    // the shipped profile it replaced, else the first one, else the default
    setModel(m_doc.modelPath(), m_drives, name);
    return true;
}

bool StationPage::importProfile(const QString& fileIn)
{
    const QString file =
        fileIn.isEmpty() ? askOpenFile(tr("Import station profile"), tr("Station profiles (*.json);;All files (*)"))
                         : fileIn;
    if (file.isEmpty()) return false;
    QString message;
    const QString name = m_doc.importFile(file, &message);
    if (name.isEmpty()) {
        showError(message);
        tell(tr("Import profile"), message);
        return false;
    }
    fillCombo();
    if (!maybeDiscard()) return true;  // imported, the edits stay on screen
    return loadStored(name);
}

bool StationPage::exportProfile(const QString& fileIn)
{
    const QString file =
        fileIn.isEmpty() ? askSaveFile(tr("Export station profile"), tr("Station profiles (*.json)"),
                                       trainer::ProfileStore::fileNameFor(m_doc.profile().name))
                         : fileIn;
    if (file.isEmpty()) return false;
    bool overwrite = false;
    if (QFileInfo::exists(file)) {
        if (!ask(tr("Export profile"), tr("%1 exists already. Replace it?").arg(file))) return false;
        overwrite = true;
    }
    QString error;
    if (!m_doc.exportTo(file, overwrite, &error)) {
        showError(tr("Cannot export the profile: %1").arg(error));
        tell(tr("Export profile"), error);
        return false;
    }
    return true;
}

void StationPage::mappingEdited()
{
    m_mappings->writeTo(m_doc.edit());
    setDirty(true);
    install(true);
}

// ---- displays ------------------------------------------------------------------

void StationPage::refresh()
{
    m_state = stationState(m_station);
    if (m_state) {
        showIssues(m_state->profileIssues);
        showBanner(*m_state);
        showDevices(*m_state);
        m_mappings->showState(*m_state);
    } else {
        showIssues(m_doc.profile().check(m_drives));
        showBanner(trainer::StationState{});
    }
    QStringList activity;
    if (isRecording())
        activity << tr("● Recording to %1 (%2 s)").arg(QFileInfo(m_recordFile).fileName()).arg(m_recordClock.elapsed() / 1000);
    if (isReplaying()) activity << tr("▶ Replaying %1").arg(QFileInfo(m_replayFile).fileName());
    const QString text = activity.join(QLatin1Char('\n'));
    if (m_activity->text() != text) m_activity->setText(text);
    m_activity->setVisible(!text.isEmpty());
}

void StationPage::showIssues(const QList<trainer::ProfileIssue>& issues)
{
    const QString key = issuesKey(issues);
    if (m_issues->property("key").toString() == key) return;
    m_issues->setProperty("key", key);
    m_issues->clear();
    for (const trainer::ProfileIssue& issue : issues) {
        auto* item = new QListWidgetItem(issue.error ? tr("Error — %1").arg(issue.text()) : tr("Warning — %1").arg(issue.text()));
        item->setBackground(issue.error ? QColor(0xfd, 0xe2, 0xe2) : QColor(0xff, 0xf4, 0xc4));
        item->setForeground(issue.error ? QColor(0x8b, 0x00, 0x00) : QColor(0x6b, 0x4a, 0x00));
        item->setToolTip(issue.text());
        m_issues->addItem(item);
    }
    // as high as its lines, up to four (then it scrolls)
    const int rows = std::min<int>(int(issues.size()), 4);
    const int rowHeight = m_issues->sizeHintForRow(0) > 0 ? m_issues->sizeHintForRow(0) : m_issues->fontMetrics().height() + 4;
    m_issues->setFixedHeight(rows * rowHeight + 2 * m_issues->frameWidth() + 2);
    m_issues->setVisible(!issues.isEmpty());
}

void StationPage::showBanner(const trainer::StationState& state)
{
    QString bank;
    if (state.bankNames.isEmpty()) {
        bank = tr("No banks");
    } else {
        const int b = std::clamp(state.activeBank, 0, int(state.bankNames.size()) - 1);
        const QString name = state.bankNames[b].isEmpty() ? tr("Bank %1").arg(b + 1) : state.bankNames[b];
        bank = state.bankNames.size() > 1 ? tr("Bank: %1 (%2 of %3)").arg(name).arg(b + 1).arg(state.bankNames.size())
                                          : tr("Bank: %1").arg(name);
        if (!state.bankSwitchHint.isEmpty()) bank += QStringLiteral("\n") + state.bankSwitchHint;
    }
    if (m_bank->text() != bank) m_bank->setText(bank);

    QStringList warnings;
    if (isReplaying())
        warnings << tr("Replaying %1: the operator's devices are ignored").arg(QFileInfo(m_replayFile).fileName());
    warnings += state.warnings;
    warnings += state.setupWarnings;  // here, for the trainer setting up (not on the operator's HUD)
    QString text;
    for (const QString& w : warnings) text += (text.isEmpty() ? QString() : QStringLiteral("\n")) + QStringLiteral("⚠ ") + w;
    if (m_warnings->text() != text) m_warnings->setText(text);
    m_warnings->setVisible(!text.isEmpty());
    const QString style =
        text.isEmpty()
            ? QStringLiteral("#stationBanner { background: #e3f2fd; border: 1px solid #90caf9; border-radius: 4px; }")
            : QStringLiteral("#stationBanner { background: #fff3e0; border: 1px solid %1; border-radius: 4px; } "
                             "#stationBanner QLabel { color: #5d4037; }")
                  .arg(amberColor().name());
    if (m_banner->styleSheet() != style) m_banner->setStyleSheet(style);
}

void StationPage::showDevices(const trainer::StationState& state)
{
    QString key;
    for (const trainer::DeviceState& d : state.devices)
        key += d.info.id + QLatin1Char('|') + d.info.name + QLatin1Char('|') + QString::number(d.replay) + QLatin1Char(';');
    if (key != m_devicesKey) {
        m_devicesKey = key;
        const QSignalBlocker block(m_devices);
        m_devices->clear();
        for (const trainer::DeviceState& d : state.devices) {
            auto* item = new QTreeWidgetItem(m_devices);
            item->setData(NameColumn, kNameRole, d.info.id);
            item->setData(NameColumn, kReplayRole, d.replay);
            const QString kind = d.replay ? tr("%1 (replay)").arg(trainer::kindName(d.info.kind))
                                          : trainer::kindName(d.info.kind);
            const QString name = trainer::displayName(d.info);
            item->setText(NameColumn, name + QLatin1Char('\n') + tr("%1 · %2").arg(kind, d.info.id));
            item->setToolTip(NameColumn, tr("%1\nKind: %2\nId: %3").arg(name, kind, d.info.id));
            item->setTextAlignment(SamplesColumn, Qt::AlignRight | Qt::AlignVCenter);
            item->setTextAlignment(DroppedColumn, Qt::AlignRight | Qt::AlignVCenter);
        }
        if (!findDevice(state, m_selectedId, m_selectedReplay) && !state.devices.isEmpty()) {
            m_selectedId = state.devices.first().info.id;
            m_selectedReplay = state.devices.first().replay;
        }
        for (int i = 0; i < m_devices->topLevelItemCount(); ++i) {
            QTreeWidgetItem* item = m_devices->topLevelItem(i);
            if (item->data(NameColumn, kNameRole).toString() == m_selectedId &&
                item->data(NameColumn, kReplayRole).toBool() == m_selectedReplay)
                m_devices->setCurrentItem(item);
        }
    }
    for (int i = 0; i < m_devices->topLevelItemCount() && i < state.devices.size(); ++i) {
        const trainer::DeviceState& d = state.devices[i];
        QTreeWidgetItem* item = m_devices->topLevelItem(i);
        const QString status = d.statusText.isEmpty() ? statusName(d.status)
                                                      : tr("%1: %2").arg(statusName(d.status), d.statusText);
        if (item->text(StatusColumn) != status) {
            item->setText(StatusColumn, status);
            item->setToolTip(StatusColumn, status);
            item->setForeground(StatusColumn, statusColor(d.status));
        }
        item->setText(SamplesColumn, QString::number(d.samples));
        item->setText(DroppedColumn, QString::number(d.dropped));
        if (d.dropped > 0) item->setForeground(DroppedColumn, amberColor());
    }
    const trainer::DeviceState* selected = findDevice(state, m_selectedId, m_selectedReplay);
    QString detail;
    if (selected && (selected->status != trainer::DeviceStatus::Connected || !selected->statusText.isEmpty()))
        detail = tr("%1 — %2").arg(trainer::displayName(selected->info), selected->statusText.isEmpty()
                                                            ? statusName(selected->status)
                                                            : statusName(selected->status) + QStringLiteral(": ") +
                                                                  selected->statusText);
    if (m_deviceDetail->text() != detail) {
        m_deviceDetail->setText(detail);
        m_deviceDetail->setStyleSheet(selected ? QStringLiteral("color: %1").arg(statusColor(selected->status).name())
                                               : QString());
    }
    m_deviceDetail->setVisible(!detail.isEmpty());
    m_channels->setDevice(selected, m_doc.edit());
    updateButtons();
}

void StationPage::updateButtons()
{
    m_save->setEnabled(m_doc.isDirty() || m_doc.origin() != ProfileDocument::Origin::User);
    m_delete->setEnabled(m_doc.origin() == ProfileDocument::Origin::User);
    const bool inProfile = !m_selectedReplay && std::any_of(m_doc.edit().devices.begin(), m_doc.edit().devices.end(),
                                                            [&](const trainer::DeviceSetting& d) {
                                                                return d.id == m_selectedId;
                                                            });
    m_removeDevice->setEnabled(inProfile);
    m_record->setEnabled(m_station != nullptr);
    m_replay->setEnabled(m_station != nullptr);
    const QString record = isRecording() ? tr("Stop recording") : tr("Record input…");
    if (m_record->text() != record) m_record->setText(record);
    const QString replay = isReplaying() ? tr("Stop replay") : tr("Replay a log…");
    if (m_replay->text() != replay) m_replay->setText(replay);
}

// ---- hooks ---------------------------------------------------------------------

bool StationPage::ask(const QString& title, const QString& question)
{
    // (the buttons' words are ours: Qt's own catalogue may not be installed)
    QMessageBox box(QMessageBox::Question, title, question, QMessageBox::Yes | QMessageBox::No, this);
    box.setDefaultButton(QMessageBox::No);
    box.button(QMessageBox::Yes)->setText(tr("Yes"));
    box.button(QMessageBox::No)->setText(tr("No"));
    return box.exec() == QMessageBox::Yes;
}

QString StationPage::askText(const QString& title, const QString& label, const QString& text)
{
    QInputDialog dialog(this);
    dialog.setWindowTitle(title);
    dialog.setLabelText(label);
    dialog.setTextValue(text);
    dialog.setOkButtonText(tr("OK"));
    dialog.setCancelButtonText(tr("Cancel"));
    return dialog.exec() == QDialog::Accepted ? dialog.textValue() : QString();
}

QString StationPage::askOpenFile(const QString& title, const QString& filter)
{
    return QFileDialog::getOpenFileName(this, title, QString(), filter);
}

QString StationPage::askSaveFile(const QString& title, const QString& filter, const QString& suggested)
{
    // the page asks itself before replacing (exportProfile), with the same words everywhere
    return QFileDialog::getSaveFileName(this, title, suggested, filter, nullptr, QFileDialog::DontConfirmOverwrite);
}

std::optional<trainer::DeviceSetting> StationPage::askSerialConsole()
{
    SerialConsoleDialog dialog(this);
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    return dialog.setting();
}

void StationPage::tell(const QString& title, const QString& message)
{
    QMessageBox box(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
    box.button(QMessageBox::Ok)->setText(tr("OK"));
    box.exec();
}

void StationPage::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    refresh();
    m_timer->start();
}

void StationPage::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    m_timer->stop();
}

void StationPage::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void StationPage::retranslate()
{
    // the spin boxes (gain…) read and show numbers in the new locale
    setLocale(QLocale());
    m_texts.apply();
    m_doc.relist();  // the profiles' names in the new language
    m_description->setText(m_doc.profile().localized(m_doc.profile().description));
    fillCombo();
    updateButtons();
    // the lists shown from the state are made again: kinds, statuses, issues
    m_devicesKey.clear();
    m_issues->setProperty("key", QVariant());
    // after the children (the channels, the mapping table) have taken the language too
    QTimer::singleShot(0, this, &StationPage::refresh);
}

}  // namespace studio
