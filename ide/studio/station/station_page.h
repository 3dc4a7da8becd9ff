#pragma once
// StationPage: padrob-studio's Station workspace (DESIGN "The station") — the
// operator's devices, their calibration and the valve mapping, kept as named station
// profiles per model.
//
//  - Profile bar: the model's profiles (the user's, and those shipped with the model,
//    marked; unreadable files listed disabled with their problem), New, Save, Save As…,
//    Delete, Import…, Export…, and the profile's issues under it (warnings amber, errors
//    red). Nothing is overwritten without asking; a shipped profile is saved as a user
//    copy. Unsaved edits are marked '*'.
//  - Banner: the active bank and the station's warnings (devices gone, levers waiting
//    for the centre, a replay driving the machine).
//  - Devices: every device of the station with its status; a serial console is added
//    to the profile; input can be recorded to a log and a log replayed.
//  - Channels of the selected device: raw and calibrated bars, flags, button lamps and
//    "Calibrate…" (CalibrationWizard).
//  - Valve mapping and banks (MappingTable).
//
// Threads: the page never touches the engine. It changes the station with
// Station::post() (a profile, a calibration, a device), or call() where it needs the
// answer (starting a recording), and reads Station::latest() on a timer at kRefreshHz
// while it is visible (stationState(): a station that is not started is asked
// directly). Every edit re-installs the profile at once (the active bank is kept);
// profileChanged() tells the main window. The main window gives the engine the model's
// drives (StationEngine::setDrives); the page only lists them.
//
// Language: on QEvent::LanguageChange every text is set again (m_texts, i18n::Texts) and the
// lists made from the state are made anew; numbers follow the locale (spin boxes too),
// profiles on disk keep '.'.
//
// Questions (overwrite? discard? a name, a file) go through virtual hooks (ask(),
// askText(), askOpenFile(), askSaveFile(), askSerialConsole(), tell()) that show
// dialogs; tests override them with scripted answers.

#include "ide/studio/station/profile_document.h"
#include "trainer/station/profile_store.h"
#include "trainer/station/station.h"
#include "ide/i18n/texts.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QPointer>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QTimer;
class QTreeWidget;
class QVBoxLayout;

namespace trainer {
class InputRecorder;
class ReplayDevice;
}  // namespace trainer

namespace studio {

class CalibrationWizard;
class ChannelPanel;
class MappingTable;

class StationPage : public QWidget {
    Q_OBJECT
public:
    static constexpr int kRefreshHz = 30;
    /// Columns of the devices list (the device's cell: its name, then kind · id; the
    /// id is also its Qt::UserRole data).
    enum DeviceColumn { NameColumn, StatusColumn, SamplesColumn, DroppedColumn, DeviceColumnCount };

    /// `station`: not owned, may be nullptr (nothing live then).
    explicit StationPage(trainer::Station* station, QWidget* parent = nullptr);
    ~StationPage() override;

    /// Where user profiles are kept (the default: under the user's configuration).
    void setProfileStore(const trainer::ProfileStore& store);
    const trainer::ProfileStore& profileStore() const { return m_doc.store(); }

    /// The model whose profiles are listed (profiles are per model file) and its drives.
    /// Loads `preferred` when it can, else the first readable profile, else the model's
    /// default profile (StationProfile::defaultFor, not saved). Unsaved edits of the
    /// previous profile are dropped: ask first (maybeDiscard()).
    void setModel(const QString& modelPath, const QList<trainer::DriveInfo>& drives, const QString& preferred = {});
    QString modelPath() const { return m_doc.modelPath(); }
    /// The same model with new drives (re-applied after an edit): the profile stays,
    /// unsaved edits too, and is installed again.
    void setDrives(const QList<trainer::DriveInfo>& drives);
    const QList<trainer::DriveInfo>& drives() const { return m_drives; }

    // ---- the profile
    const trainer::StationProfile& profile() const { return m_doc.profile(); }
    bool isDirty() const { return m_doc.isDirty(); }
    /// The profile came from (or was saved to) the user's folder / ships with the model.
    bool isUserProfile() const { return m_doc.origin() == ProfileDocument::Origin::User; }
    bool isShippedProfile() const { return m_doc.origin() == ProfileDocument::Origin::Shipped; }
    /// The model's profiles as the combo lists them.
    const QList<trainer::StoredProfile>& storedProfiles() const { return m_doc.stored(); }
    /// The last error of loading, saving, importing or exporting ("" none; cleared by
    /// the next success).
    QString lastError() const;
    /// True when there are no unsaved edits, or the person agrees to drop them.
    bool maybeDiscard();

    /// Loads a stored profile and installs it. False (the current one stays, the error
    /// is shown) when it cannot be read, or unsaved edits are kept.
    bool loadProfile(const QString& name);
    /// A new empty profile with one bank (`name` "" asks for one).
    bool newProfile(const QString& name = {});
    /// Saves under the profile's name (a shipped profile as a user copy); asks before
    /// replacing another file.
    bool save();
    /// Saves under another name (`name` "" asks for one); asks before replacing.
    bool saveAs(const QString& name = {});
    /// Deletes the user profile shown (after asking) and loads another.
    bool deleteProfile();
    /// Imports a profile file (`file` "" asks) into the store and loads it.
    bool importProfile(const QString& file = {});
    /// Writes the profile to a file (`file` "" asks); asks before replacing one.
    bool exportProfile(const QString& file = {});

    // ---- devices
    /// Adds a serial console to the profile (`setting.id` "" asks) and re-installs it.
    bool addSerialConsole(const trainer::DeviceSetting& setting = {});
    /// Removes the selected device from the profile (only devices the profile lists).
    bool removeSelectedDevice();
    void selectDevice(const QString& id, bool replay = false);
    QString selectedDeviceId() const { return m_selectedId; }
    /// Records what the station reads to a log (`file` "" asks).
    bool startRecording(const QString& file = {});
    bool stopRecording();
    bool isRecording() const { return bool(m_recorder); }
    /// Replays a log (`file` "" asks): its devices drive the machine, the operator's are
    /// ignored until stopReplay().
    bool startReplay(const QString& file = {});
    void stopReplay();
    bool isReplaying() const { return !m_replays.empty(); }

    // ---- calibration
    /// Opens the calibration wizard for `axis` of the selected device (window-modal, not
    /// blocking); nullptr when there is no such channel, or the device is the keyboard
    /// (keys are digital: the channel panel offers a ramp instead, setKeyRamp()).
    CalibrationWizard* calibrate(int axis);
    /// The selected keyboard's channel `axis` reaches its full command in `seconds` (0: at
    /// once): the low-pass of its calibration, kept in the profile.
    void setKeyRamp(int axis, double seconds);
    /// Keeps a calibration in the profile (dirty) and gives it to the station.
    void applyCalibration(const QString& deviceMatch, int axis, const trainer::ChannelCalibration& calibration);

    /// Reads the station's state now and updates every display (the timer does this at
    /// kRefreshHz while the page is visible).
    void refresh();
    /// The state shown last (nullptr before the first).
    std::shared_ptr<const trainer::StationState> shownState() const { return m_state; }

    // ---- widgets, for tests and the main window
    QComboBox* profileCombo() const { return m_profiles; }
    QListWidget* issuesList() const { return m_issues; }
    QLabel* errorLabel() const { return m_error; }
    QLabel* bankLabel() const { return m_bank; }
    QLabel* descriptionLabel() const { return m_description; }
    QLabel* warningsLabel() const { return m_warnings; }
    QTreeWidget* devicesList() const { return m_devices; }
    /// The selected device's status in full when it is not well ("" hidden).
    QLabel* deviceDetailLabel() const { return m_deviceDetail; }
    ChannelPanel* channelPanel() const { return m_channels; }
    MappingTable* mappingTable() const { return m_mappings; }
    QPushButton* saveButton() const { return m_save; }
    QPushButton* deleteButton() const { return m_delete; }
    QPushButton* removeDeviceButton() const { return m_removeDevice; }
    QPushButton* recordButton() const { return m_record; }
    QPushButton* replayButton() const { return m_replay; }

signals:
    /// The profile in use changed (loaded, edited, calibrated, saved under a name).
    void profileChanged(const trainer::StationProfile& profile);
    void dirtyChanged(bool dirty);

protected:
    /// A yes/no question; true: yes.
    virtual bool ask(const QString& title, const QString& question);
    /// A line of text ("" cancelled).
    virtual QString askText(const QString& title, const QString& label, const QString& text);
    /// A file to read / to write ("" cancelled). askSaveFile need not confirm replacing.
    virtual QString askOpenFile(const QString& title, const QString& filter);
    virtual QString askSaveFile(const QString& title, const QString& filter, const QString& suggested);
    /// The serial console dialog (nullopt cancelled).
    virtual std::optional<trainer::DeviceSetting> askSerialConsole();
    /// Tells of a failure.
    virtual void tell(const QString& title, const QString& message);

    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;
    /// QEvent::LanguageChange: retranslate().
    void changeEvent(QEvent* event) override;

private:
    // item data roles: the profiles' list, the devices' list
    static constexpr int kNameRole = Qt::UserRole;
    static constexpr int kStoredRole = Qt::UserRole + 1;  ///< false: the unsaved profile's item
    static constexpr int kReplayRole = Qt::UserRole + 1;  ///< the devices' list: a replay
    void retranslate();
    void buildProfileBar(QVBoxLayout* layout);
    QWidget* buildDevices(QWidget* parent);
    /// Shows the document's profile as the current one (mapping, description, combo,
    /// buttons) and installs it; `wasDirty`: before it changed (dirtyChanged()).
    void showCurrent(bool wasDirty);
    void setDirty(bool dirty);
    void install(bool keepBank);
    void fillCombo();
    void profileActivated(int index);
    bool loadStored(const QString& name);
    bool saveUnder(const QString& name, bool askBeforeReplacing);
    void showError(const QString& text);
    void clearError();
    void mappingEdited();
    void showIssues(const QList<trainer::ProfileIssue>& issues);
    void showBanner(const trainer::StationState& state);
    void showDevices(const trainer::StationState& state);
    void updateButtons();

    QPointer<trainer::Station> m_station;
    QList<trainer::DriveInfo> m_drives;
    ProfileDocument m_doc;  ///< the profile edited, its origin and its files

    std::shared_ptr<const trainer::StationState> m_state;
    QString m_selectedId;
    bool m_selectedReplay = false;
    QString m_devicesKey;

    std::unique_ptr<trainer::InputRecorder> m_recorder;  ///< used only in the input thread (call())
    QString m_recordFile;
    QElapsedTimer m_recordClock;
    std::vector<std::shared_ptr<trainer::ReplayDevice>> m_replays;
    QString m_replayFile;
    QPointer<CalibrationWizard> m_wizard;

    QTimer* m_timer = nullptr;
    i18n::Texts m_texts;  ///< the texts that follow the language
    QComboBox* m_profiles = nullptr;
    QPushButton* m_new = nullptr;
    QPushButton* m_save = nullptr;
    QPushButton* m_saveAs = nullptr;
    QPushButton* m_delete = nullptr;
    QPushButton* m_import = nullptr;
    QPushButton* m_export = nullptr;
    QLabel* m_description = nullptr;
    QLabel* m_error = nullptr;
    QListWidget* m_issues = nullptr;
    QWidget* m_banner = nullptr;
    QLabel* m_bank = nullptr;
    QLabel* m_warnings = nullptr;
    QTreeWidget* m_devices = nullptr;
    QLabel* m_deviceDetail = nullptr;
    QPushButton* m_addSerial = nullptr;
    QPushButton* m_removeDevice = nullptr;
    QPushButton* m_record = nullptr;
    QPushButton* m_replay = nullptr;
    QLabel* m_activity = nullptr;
    ChannelPanel* m_channels = nullptr;
    MappingTable* m_mappings = nullptr;
};

}  // namespace studio
