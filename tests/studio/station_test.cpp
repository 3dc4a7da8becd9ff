// The Station workspace (ide/studio/station/) as a real window: profiles (shipped and
// user, new, save, save as, never overwriting without asking, corrupt and future files
// refused with their reason), the devices list and the channel bars following a fake
// device, the calibration wizard from rest to finish, the mapping table driving the
// engine's commands, banks and the banner, serial consoles, record and replay, and
// screenshots of the page and of each wizard page, in English and in Spanish; a switch
// of language at run time re-words the page and its numbers take the decimal comma.
//
// The station is not started in most tests: post() then runs at once, and the test
// steps the engine itself (call → update). One test runs a started station, as the
// application does.

#include "tests/studio/gui_test.h"
#include "../trainer/fake_device.h"

#include "ide/i18n/language.h"
#include "ide/studio/station/calibration_wizard.h"
#include "ide/studio/station/channel_bars.h"
#include "ide/studio/station/curve_plot.h"
#include "ide/studio/station/live_state.h"
#include "ide/studio/station/mapping_table.h"
#include "ide/studio/station/serial_console_dialog.h"
#include "ide/studio/station/station_page.h"
#include "trainer/input/input_device.h"
#include "trainer/input/keyboard_device.h"
#include "trainer/station/control_names.h"
#include "trainer/station/profile_store.h"
#include "trainer/station/station.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGroupBox>
#include <QHeaderView>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <deque>

using studio::CalibrationWizard;
using studio::MappingTable;
using studio::StationPage;
using studio::test::screenshotPath;

namespace {

using test::FakeDevice;

// ---- the page with scripted answers -----------------------------------------------

class TestPage : public StationPage {
public:
    using StationPage::StationPage;
    std::deque<bool> answers;  ///< ask(): popped; empty → fail the test (an unexpected question)
    QStringList questions;
    QString text, openFile, saveFile;
    std::optional<trainer::DeviceSetting> serial;
    QStringList told;

protected:
    bool ask(const QString&, const QString& question) override
    {
        questions << question;
        if (answers.empty()) {
            qWarning("unexpected question: %s", qPrintable(question));
            return false;
        }
        const bool a = answers.front();
        answers.pop_front();
        return a;
    }
    QString askText(const QString&, const QString&, const QString&) override { return text; }
    QString askOpenFile(const QString&, const QString&) override { return openFile; }
    QString askSaveFile(const QString&, const QString&, const QString&) override { return saveFile; }
    std::optional<trainer::DeviceSetting> askSerialConsole() override { return serial; }
    void tell(const QString&, const QString& message) override { told << message; }
};

QList<trainer::DriveInfo> linerDrives()
{
    const char* names[] = {"GIRO PLUMA", "LEVANTE PLUMA", "EXTENSIÓN", "GIRO MUÑECA", "LEVANTE MUÑECA",
                           "ROTACIÓN MUÑECA", "PISTÓN", "GARRA SUPERIOR", "GARRA INFERIOR"};
    QList<trainer::DriveInfo> d;
    for (int i = 0; i < 9; ++i) d.append({i, i + 1, QString::fromUtf8(names[i])});
    return d;
}

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeFile(const QString& path, const QByteArray& data)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(data) == data.size();
}

/// A model folder with a shipped profile next to the model, a user store, a station
/// (not started) with the liner's drives and a fake gamepad, and the page.
struct Rig {
    QTemporaryDir dir;
    QString modelPath;
    QString userRoot;
    trainer::Station station;
    std::shared_ptr<FakeDevice> pad;
    std::unique_ptr<TestPage> page;
    double t = 0.0;

    /// `sdlRange`: the pad reads −32768…32767 (as SDL does), else −100…100.
    explicit Rig(bool withShipped = true, int axes = 4, int buttons = 6, bool sdlRange = false)
        : pad(std::make_shared<FakeDevice>("sdl:0300fake", trainer::DeviceKind::Gamepad, axes, buttons,
                                           sdlRange ? -32768 : -100, 0, sdlRange ? 32767 : 100, "Fake Pad"))
    {
        modelPath = dir.filePath("models/liner_manipulator.pad");
        const QByteArray model = readAll(QStringLiteral(PADROB_SOURCE_DIR) + "/models/liner_manipulator.pad");
        writeFile(modelPath, model);
        if (withShipped) {
            trainer::StationProfile shipped = trainer::StationProfile::defaultFor("liner_manipulator", linerDrives());
            shipped.name = "Gamepad";
            writeFile(dir.filePath("models/liner_manipulator.station/gamepad.json"), shipped.toJson());
        }
        userRoot = dir.filePath("user");
        station.call([](trainer::StationEngine& e) { e.setDrives(9, linerDrives()); });
        station.post([p = pad](trainer::StationEngine& e) { e.addDevice(p); });
        page = std::make_unique<TestPage>(&station);
        page->setProfileStore(trainer::ProfileStore(userRoot));
        page->setModel(modelPath, linerDrives());
    }
    QString userFile(const QString& name) const
    {
        return userRoot + "/liner_manipulator/" + trainer::ProfileStore::fileNameFor(name);
    }
    /// n engine cycles of 1 ms, then the page reads the state.
    void step(int n = 1)
    {
        station.call([&](trainer::StationEngine& e) {
            for (int i = 0; i < n; ++i) e.update(t += 1e-3);
        });
        page->refresh();
    }
    trainer::StationProfile engineProfile()
    {
        trainer::StationProfile p;
        station.call([&](trainer::StationEngine& e) { p = e.profile(); });
        return p;
    }
    std::vector<double> commands()
    {
        std::vector<double> u;
        station.call([&](trainer::StationEngine& e) { u = e.commands(); });
        return u;
    }
    void press(int button)
    {
        pad->setButton(button, true);
        step();
        pad->setButton(button, false);
        step();
    }
};

int comboIndexOf(QComboBox* c, const QString& name)
{
    for (int i = 0; i < c->count(); ++i)
        if (c->itemData(i, Qt::UserRole).toString() == name) return i;
    return -1;
}

bool itemEnabled(QComboBox* c, int i)
{
    auto* model = qobject_cast<QStandardItemModel*>(c->model());
    return model && model->item(i)->isEnabled();
}

QTreeWidgetItem* deviceRow(QTreeWidget* list, const QString& id)
{
    for (int i = 0; i < list->topLevelItemCount(); ++i)
        if (list->topLevelItem(i)->data(StationPage::NameColumn, Qt::UserRole).toString() == id)
            return list->topLevelItem(i);
    return nullptr;
}

}  // namespace

class StationTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void profileListShowsShippedAndUserAndLoadsOne();
    void defaultProfileWhenTheModelHasNone();
    void newSaveAndSaveAs();
    void savingOverAnExistingNameAsks();
    void savingItsOwnFileAsksOnlyWhenChangedOnDisk();
    void shippedProfileIsSavedAsAUserCopy();
    void deleteReturnsToTheShippedProfile();
    void corruptProfileIsListedUnreadableAndKeepsTheCurrentOne();
    void importOfAFutureVersionIsRefused();
    void importAndExport();
    void unsavedEditsAreKeptWhenTheAnswerIsNo();
    void devicesListShowsTheDeviceAndItsStatus();
    void channelBarsFollowTheAxis();
    void wizardCapturesAndFinishes();
    void wizardOnATrigger();
    void keyboardChannelsOfferARampNotTheWizard();
    void gamepadControlsAreNamed();
    void mappingTableDrivesTheCommand();
    void mappingToAMissingDriveShowsItsIssue();
    void bankBannerFollowsABankSwitch();
    void serialConsoleIsAddedAndRemoved();
    void recordAndReplay();
    void runningStationFollowsTheLever();
    void languageSwitchesAtRunTime();
    void shippedProfileAndKeyboardReadInSpanish();
    void screenshots();
    void cleanupTestCase();
};

// ---- profiles ------------------------------------------------------------------

void StationTest::initTestCase()
{
    // the texts the tests compare are the English ones (whatever the system's language)
    QVERIFY(i18n::install("en"));
}

void StationTest::cleanupTestCase()
{
    i18n::install("en");
}

void StationTest::profileListShowsShippedAndUserAndLoadsOne()
{
    Rig rig;
    // a user profile, saved through the store
    trainer::StationProfile mine;
    mine.name = "Mine";
    mine.banks.append({"Boom", {}, {{"gamepad", 1, 2, 1.0, -1}}});
    QVERIFY(trainer::ProfileStore(rig.userRoot).save(rig.modelPath, mine, trainer::ProfileStore::SaveMode::CreateOnly));
    rig.page->setModel(rig.modelPath, linerDrives());

    QComboBox* combo = rig.page->profileCombo();
    QCOMPARE(combo->count(), 2);
    QCOMPARE(combo->itemText(0), QStringLiteral("Mine"));
    QCOMPARE(combo->itemText(1), QStringLiteral("Gamepad (shipped)"));
    // the user's come first, and the first is loaded
    QCOMPARE(rig.page->profile().name, QStringLiteral("Mine"));
    QVERIFY(rig.page->isUserProfile());
    QVERIFY(!rig.page->isDirty());
    QCOMPARE(rig.engineProfile().name, QStringLiteral("Mine"));
    QVERIFY(rig.page->deleteButton()->isEnabled());

    // choosing the shipped one loads and installs it
    QSignalSpy changed(rig.page.get(), &StationPage::profileChanged);
    QVERIFY(rig.page->loadProfile("Gamepad"));
    QCOMPARE(rig.page->profile().name, QStringLiteral("Gamepad"));
    QVERIFY(rig.page->isShippedProfile());
    QCOMPARE(rig.engineProfile(), rig.page->profile());
    QCOMPARE(combo->currentText(), QStringLiteral("Gamepad (shipped)"));
    QVERIFY(!rig.page->deleteButton()->isEnabled());
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.first().first().value<trainer::StationProfile>().name, QStringLiteral("Gamepad"));
    QVERIFY(rig.page->mappingTable()->rowCount() > 0);

    // the combo's own signal does the same
    combo->activated(comboIndexOf(combo, "Mine"));
    QCOMPARE(rig.page->profile().name, QStringLiteral("Mine"));
}

void StationTest::defaultProfileWhenTheModelHasNone()
{
    Rig rig(false);
    QCOMPARE(rig.page->storedProfiles().size(), 0);
    const trainer::StationProfile expected = trainer::StationProfile::defaultFor("liner_manipulator", linerDrives());
    QCOMPARE(rig.page->profile(), expected);
    QVERIFY(!rig.page->isUserProfile() && !rig.page->isShippedProfile());
    QVERIFY(rig.page->profileCombo()->currentText().contains("not saved"));
    QCOMPARE(rig.engineProfile(), expected);
    QVERIFY(rig.page->saveButton()->isEnabled());
    QVERIFY(rig.page->save());
    QVERIFY(QFileInfo::exists(rig.userFile(expected.name)));
    QVERIFY(rig.page->isUserProfile());
}

void StationTest::newSaveAndSaveAs()
{
    Rig rig;
    QSignalSpy dirty(rig.page.get(), &StationPage::dirtyChanged);
    rig.page->text = "Fresh";
    QVERIFY(rig.page->newProfile());
    QCOMPARE(rig.page->profile().name, QStringLiteral("Fresh"));
    QCOMPARE(rig.page->profile().banks.size(), 1);
    QVERIFY(rig.page->profile().always.isEmpty());
    QVERIFY(rig.page->isDirty());
    QCOMPARE(dirty.count(), 1);
    QCOMPARE(rig.page->profileCombo()->currentText(), QStringLiteral("Fresh (not saved) *"));
    QCOMPARE(rig.engineProfile().name, QStringLiteral("Fresh"));

    QVERIFY(rig.page->save());
    QVERIFY(!rig.page->isDirty());
    QVERIFY(rig.page->isUserProfile());
    QVERIFY(QFileInfo::exists(rig.userFile("Fresh")));
    QCOMPARE(rig.page->profileCombo()->currentText(), QStringLiteral("Fresh"));
    QVERIFY(rig.page->questions.isEmpty());

    // an edit marks it
    rig.page->mappingTable()->addMapping();
    QVERIFY(rig.page->isDirty());
    QCOMPARE(rig.page->profileCombo()->currentText(), QStringLiteral("Fresh *"));

    QVERIFY(rig.page->saveAs("Copy"));
    QCOMPARE(rig.page->profile().name, QStringLiteral("Copy"));
    QVERIFY(!rig.page->isDirty());
    trainer::StationProfile saved;
    QList<trainer::ProfileIssue> issues;
    QVERIFY(trainer::ProfileStore(rig.userRoot).load(rig.modelPath, "Copy", saved, issues));
    QCOMPARE(saved.banks.value(0).mappings.size(), 1);
    // the first file kept its content (no mapping)
    QVERIFY(trainer::ProfileStore(rig.userRoot).load(rig.modelPath, "Fresh", saved, issues));
    QCOMPARE(saved.banks.value(0).mappings.size(), 0);
    QCOMPARE(rig.page->storedProfiles().size(), 3);  // Copy, Fresh, Gamepad (shipped)

    // a name typed in the dialog
    rig.page->text = "Third";
    QVERIFY(rig.page->saveAs());
    QVERIFY(QFileInfo::exists(rig.userFile("Third")));
    rig.page->text.clear();
    QVERIFY(!rig.page->saveAs());  // cancelled
}

void StationTest::savingOverAnExistingNameAsks()
{
    Rig rig;
    QVERIFY(rig.page->newProfile("Mine"));
    QVERIFY(rig.page->save());
    const QByteArray before = readAll(rig.userFile("Mine"));
    QVERIFY(!before.isEmpty());

    QVERIFY(rig.page->newProfile("Other"));
    rig.page->mappingTable()->addMapping();
    rig.page->answers = {false};
    QVERIFY(!rig.page->saveAs("Mine"));
    QCOMPARE(rig.page->questions.size(), 1);
    QVERIFY(rig.page->questions.first().contains("Mine"));
    QCOMPARE(readAll(rig.userFile("Mine")), before);  // unchanged
    QVERIFY(rig.page->isDirty());
    QCOMPARE(rig.page->profile().name, QStringLiteral("Other"));

    // a new profile under a taken name asks as well on Save (after the question to discard)
    rig.page->answers = {true, false};
    rig.page->questions.clear();
    QVERIFY(rig.page->newProfile("Mine"));
    QVERIFY(!rig.page->save());
    QCOMPARE(rig.page->questions.size(), 2);
    QCOMPARE(readAll(rig.userFile("Mine")), before);

    // yes replaces it
    rig.page->mappingTable()->addMapping();
    rig.page->answers = {true};
    QVERIFY(rig.page->save());
    QVERIFY(readAll(rig.userFile("Mine")) != before);
    QVERIFY(!rig.page->isDirty());
}

void StationTest::savingItsOwnFileAsksOnlyWhenChangedOnDisk()
{
    Rig rig;
    QVERIFY(rig.page->newProfile("Mine"));
    QVERIFY(rig.page->save());
    rig.page->mappingTable()->addMapping();
    rig.page->questions.clear();
    QVERIFY(rig.page->save());  // its own file: no question
    QVERIFY(rig.page->questions.isEmpty());

    // someone else wrote it meanwhile: asked, and No keeps theirs
    QTest::qWait(20);
    trainer::StationProfile theirs;
    theirs.name = "Mine";
    theirs.description = "theirs";
    QVERIFY(writeFile(rig.userFile("Mine"), theirs.toJson()));
    {
        QFile f(rig.userFile("Mine"));
        QVERIFY(f.open(QIODevice::ReadWrite));
        QVERIFY(f.setFileTime(QDateTime::currentDateTime().addSecs(5), QFileDevice::FileModificationTime));
    }
    rig.page->mappingTable()->addMapping();
    rig.page->answers = {false};
    QVERIFY(!rig.page->save());
    QCOMPARE(rig.page->questions.size(), 1);
    QCOMPARE(readAll(rig.userFile("Mine")), theirs.toJson());
}

void StationTest::shippedProfileIsSavedAsAUserCopy()
{
    Rig rig;
    QVERIFY(rig.page->loadProfile("Gamepad"));
    const QString shippedFile = rig.dir.filePath("models/liner_manipulator.station/gamepad.json");
    const QByteArray shipped = readAll(shippedFile);
    QVERIFY(rig.page->saveButton()->isEnabled());
    rig.page->mappingTable()->gainSpin(0)->setValue(0.25);
    QVERIFY(rig.page->isDirty());
    QCOMPARE(rig.page->profileCombo()->currentText(), QStringLiteral("Gamepad (shipped) *"));
    QVERIFY(rig.page->save());
    QCOMPARE(readAll(shippedFile), shipped);  // never written
    QVERIFY(QFileInfo::exists(rig.userFile("Gamepad")));
    QVERIFY(rig.page->isUserProfile());
    // the user copy now takes the shipped one's place in the list
    QCOMPARE(rig.page->profileCombo()->count(), 1);
    QCOMPARE(rig.page->profileCombo()->currentText(), QStringLiteral("Gamepad"));
}

void StationTest::deleteReturnsToTheShippedProfile()
{
    Rig rig;
    QVERIFY(rig.page->loadProfile("Gamepad"));
    rig.page->mappingTable()->gainSpin(0)->setValue(0.25);
    QVERIFY(rig.page->save());
    QVERIFY(rig.page->isUserProfile());
    rig.page->answers = {false};
    QVERIFY(!rig.page->deleteProfile());
    QVERIFY(QFileInfo::exists(rig.userFile("Gamepad")));
    rig.page->answers = {true};
    QVERIFY(rig.page->deleteProfile());
    QVERIFY(!QFileInfo::exists(rig.userFile("Gamepad")));
    QVERIFY(rig.page->isShippedProfile());
    QCOMPARE(rig.page->profile().always.value(0).gain, 1.0);
    QVERIFY(!rig.page->deleteProfile());  // shipped: not deletable
}

void StationTest::corruptProfileIsListedUnreadableAndKeepsTheCurrentOne()
{
    Rig rig;
    QVERIFY(rig.page->newProfile("Good"));
    QVERIFY(rig.page->save());
    QVERIFY(writeFile(rig.userFile("Broken"), "{ \"format\": \"padrob-station-profile\", \"version\": 1, oops"));
    rig.page->setModel(rig.modelPath, linerDrives(), "Good");
    QComboBox* combo = rig.page->profileCombo();
    const int broken = comboIndexOf(combo, "Broken");
    QVERIFY(broken >= 0);
    QCOMPARE(combo->itemText(broken), QStringLiteral("Broken (unreadable)"));
    QVERIFY(!itemEnabled(combo, broken));
    QVERIFY(!combo->itemData(broken, Qt::ToolTipRole).toString().isEmpty());
    QVERIFY(itemEnabled(combo, comboIndexOf(combo, "Good")));

    QCOMPARE(rig.page->profile().name, QStringLiteral("Good"));
    QVERIFY(!rig.page->loadProfile("Broken"));
    QVERIFY(rig.page->lastError().contains("Broken"));
    QVERIFY(rig.page->errorLabel()->isVisibleTo(rig.page.get()));
    QCOMPARE(rig.page->profile().name, QStringLiteral("Good"));
    QCOMPARE(rig.engineProfile().name, QStringLiteral("Good"));
    QCOMPARE(combo->currentText(), QStringLiteral("Good"));
    // the next good load clears the error
    QVERIFY(rig.page->loadProfile("Gamepad"));
    QVERIFY(rig.page->lastError().isEmpty());
}

void StationTest::importOfAFutureVersionIsRefused()
{
    Rig rig;
    const QString file = rig.dir.filePath("future.json");
    QVERIFY(writeFile(file, R"({"format":"padrob-station-profile","version":99,"name":"From the future"})"));
    const QString before = rig.page->profile().name;
    rig.page->openFile = file;
    QVERIFY(!rig.page->importProfile());
    QCOMPARE(rig.page->told.size(), 1);
    QVERIFY2(rig.page->told.first().contains("newer"), qPrintable(rig.page->told.first()));
    QVERIFY(rig.page->lastError().contains("newer"));
    QCOMPARE(rig.page->profile().name, before);
    QCOMPARE(rig.page->storedProfiles().size(), 1);  // only the shipped one
    QVERIFY(!QFileInfo::exists(rig.userFile("From the future")));
}

void StationTest::importAndExport()
{
    Rig rig;
    QVERIFY(rig.page->loadProfile("Gamepad"));
    const QString file = rig.dir.filePath("out/exported.json");
    QDir().mkpath(rig.dir.filePath("out"));
    rig.page->saveFile = file;
    QVERIFY(rig.page->exportProfile());
    QVERIFY(QFileInfo::exists(file));
    // exporting over it asks
    rig.page->answers = {false};
    QVERIFY(!rig.page->exportProfile(file));
    QCOMPARE(rig.page->questions.size(), 1);
    // importing it: "Gamepad" is taken, so "Gamepad (2)", loaded
    QVERIFY(rig.page->importProfile(file));
    QCOMPARE(rig.page->profile().name, QStringLiteral("Gamepad (2)"));
    QVERIFY(rig.page->isUserProfile());
    QCOMPARE(rig.page->storedProfiles().size(), 2);
}

void StationTest::unsavedEditsAreKeptWhenTheAnswerIsNo()
{
    Rig rig;
    QVERIFY(rig.page->newProfile("Draft"));
    rig.page->mappingTable()->addMapping();
    rig.page->answers = {false};
    QVERIFY(!rig.page->loadProfile("Gamepad"));
    QCOMPARE(rig.page->profile().name, QStringLiteral("Draft"));
    QVERIFY(rig.page->isDirty());
    QCOMPARE(rig.page->mappingTable()->rowCount(), 1);
    QVERIFY(rig.page->profileCombo()->currentText().startsWith("Draft"));
    rig.page->answers = {true};
    QVERIFY(rig.page->loadProfile("Gamepad"));
    QVERIFY(!rig.page->isDirty());
}

// ---- devices and channels --------------------------------------------------------

void StationTest::devicesListShowsTheDeviceAndItsStatus()
{
    Rig rig;
    rig.step();
    QTreeWidget* list = rig.page->devicesList();
    QTreeWidgetItem* row = deviceRow(list, "sdl:0300fake");
    QVERIFY(row);
    QCOMPARE(row->text(StationPage::NameColumn),
             "Fake Pad\n" + trainer::kindName(trainer::DeviceKind::Gamepad) + " · sdl:0300fake");
    QCOMPARE(row->text(StationPage::StatusColumn), QStringLiteral("Connected"));
    QCOMPARE(row->text(StationPage::SamplesColumn), QStringLiteral("1"));
    QCOMPARE(rig.page->selectedDeviceId(), QStringLiteral("sdl:0300fake"));
    QVERIFY(!rig.page->removeDeviceButton()->isEnabled());  // not a profile device

    rig.pad->setStatus(trainer::DeviceStatus::Disconnected);
    rig.step();
    row = deviceRow(list, "sdl:0300fake");
    QCOMPARE(row->text(StationPage::StatusColumn), QStringLiteral("Disconnected: unplugged"));
    QCOMPARE(row->foreground(StationPage::StatusColumn).color(), studio::statusColor(trainer::DeviceStatus::Disconnected));
    QCOMPARE(rig.page->deviceDetailLabel()->text(), QStringLiteral("Fake Pad — Disconnected: unplugged"));
    QVERIFY(rig.page->deviceDetailLabel()->isVisibleTo(rig.page.get()));
    // its drives hold: the banner says so (the Gamepad profile maps the gamepad)
    QVERIFY(rig.page->loadProfile("Gamepad"));
    rig.step();
    QVERIFY2(rig.page->warningsLabel()->text().contains("Fake Pad"), qPrintable(rig.page->warningsLabel()->text()));
    QVERIFY(rig.page->warningsLabel()->isVisibleTo(rig.page.get()));
    rig.pad->setStatus(trainer::DeviceStatus::Connected);
    rig.step();
    QCOMPARE(deviceRow(list, "sdl:0300fake")->text(StationPage::StatusColumn), QStringLiteral("Connected"));
    QVERIFY(!rig.page->deviceDetailLabel()->isVisibleTo(rig.page.get()));
}

void StationTest::channelBarsFollowTheAxis()
{
    Rig rig;
    QVERIFY(rig.page->newProfile("Blank"));  // no calibrations: the nominal ranges
    rig.pad->setAxis(0, 50);
    rig.pad->setAxis(2, -100);
    rig.pad->setButton(3, true);
    rig.step();
    studio::ChannelPanel* panel = rig.page->channelPanel();
    QCOMPARE(panel->channelCount(), 4);
    QCOMPARE(panel->rawBar(0)->value(), 50.0);
    QCOMPARE(panel->rawBar(0)->minimum(), -100.0);
    QCOMPARE(panel->rawBar(0)->maximum(), 100.0);
    QCOMPARE(panel->rawBar(0)->fraction(), 0.75);
    QCOMPARE(panel->rawLabel(0)->text(), QStringLiteral("50"));
    QCOMPARE(panel->valueBar(0)->value(), 0.5);
    QCOMPARE(panel->valueLabel(0)->text(), QStringLiteral("+0.50"));
    QCOMPARE(panel->valueBar(2)->value(), -1.0);
    QCOMPARE(panel->valueLabel(2)->text(), QStringLiteral("−1.00"));
    QCOMPARE(panel->flagLabel(0)->text(), QStringLiteral("not calibrated"));
    QCOMPARE(panel->buttonCount(), 6);
    QVERIFY(panel->lamp(3)->isOn());
    QVERIFY(!panel->lamp(2)->isOn());

    rig.pad->setAxis(0, -25);
    rig.pad->setButton(3, false);
    rig.step();
    QCOMPARE(panel->rawBar(0)->value(), -25.0);
    QCOMPARE(panel->valueBar(0)->value(), -0.25);
    QVERIFY(!panel->lamp(3)->isOn());

    // a calibrated channel: no flag; beyond its range: "out of range"
    trainer::ChannelCalibration c{-50, 0, 50};
    c.captured = true;
    rig.page->applyCalibration("sdl:0300fake", 0, c);
    rig.step();
    QCOMPARE(panel->flagLabel(0)->text(), QString());
    QCOMPARE(panel->rawBar(0)->minimum(), -50.0);
    QCOMPARE(panel->valueBar(0)->value(), -0.5);
    rig.pad->setAxis(0, 90);
    rig.step();
    QCOMPARE(panel->flagLabel(0)->text(), QStringLiteral("out of range"));
}

void StationTest::wizardCapturesAndFinishes()
{
    Rig rig;
    rig.page->show();
    QVERIFY(QTest::qWaitForWindowExposed(rig.page.get()));
    rig.step();
    QVERIFY(!rig.page->calibrate(7));  // no such channel
    CalibrationWizard* wizard = rig.page->calibrate(0);
    QVERIFY(wizard);
    QPointer<CalibrationWizard> guard(wizard);
    wizard->setLiveInput(false);
    wizard->setRestReadings(5);
    QVERIFY(QTest::qWaitForWindowExposed(wizard));
    QCOMPARE(wizard->currentId(), int(CalibrationWizard::RestPage));
    QAbstractButton* next = wizard->button(QWizard::NextButton);
    QVERIFY(!next->isEnabled());

    // page 1: at rest
    for (double raw : {2.0, 3.0, 1.0, 2.0}) wizard->addReading(raw);
    QVERIFY(!next->isEnabled());
    wizard->addReading(2.0);
    QVERIFY(next->isEnabled());
    QCOMPARE(wizard->capture().restCount(), 5);
    QCOMPARE(wizard->capture().centre(), 2.0);
    QCOMPARE(wizard->capture().restSpread(), 2.0);
    QVERIFY(wizard->restText()->text().contains("Spread: 2"));
    wizard->addReading(40.0);  // after the capture: not counted
    QCOMPARE(wizard->capture().restCount(), 5);
    QVERIFY(wizard->grab().save(screenshotPath("station_wizard_rest_en.png")));

    // page 2: the full travel
    wizard->next();
    QCOMPARE(wizard->currentId(), int(CalibrationWizard::TravelPage));
    QVERIFY(!next->isEnabled());
    for (double raw : {2.0, 10.0, 20.0}) wizard->addReading(raw);
    QVERIFY(!next->isEnabled());  // 18 of a 200 span: not enough
    for (double raw : {60.0, 100.0, 40.0, -20.0, -90.0, 0.0}) wizard->addReading(raw);
    QVERIFY(next->isEnabled());
    QCOMPARE(wizard->capture().seenMin(), -90.0);
    QCOMPARE(wizard->capture().seenMax(), 100.0);
    QCOMPARE(wizard->travelBar()->value(), 0.0);
    QVERIFY(wizard->grab().save(screenshotPath("station_wizard_travel_en.png")));

    // page 3: settings
    wizard->next();
    QCOMPARE(wizard->currentId(), int(CalibrationWizard::SettingsPage));
    QVERIFY(wizard->anyKindRadio()->isChecked());  // a gamepad: kept for any gamepad
    QCOMPARE(wizard->deviceMatch(), QStringLiteral("gamepad"));
    wizard->deadBandLowSpin()->setValue(10);
    wizard->deadBandHighSpin()->setValue(5);
    wizard->invertedCheck()->setChecked(true);
    QVERIFY(!wizard->exponentSpin()->isEnabled());
    wizard->curveCombo()->setCurrentIndex(1);
    QVERIFY(wizard->exponentSpin()->isEnabled());
    wizard->exponentSpin()->setValue(3.0);
    wizard->addReading(51.0);  // halfway up: inverted, exponential
    const trainer::ChannelCalibration c = wizard->calibration();
    QCOMPARE(c.rawMin, -90.0);
    QCOMPARE(c.rawCentre, 2.0);
    QCOMPARE(c.rawMax, 100.0);
    QCOMPARE(c.deadBandLow, 0.10);
    QCOMPARE(c.deadBandHigh, 0.05);
    QVERIFY(c.inverted);
    QCOMPARE(c.curve, trainer::ResponseCurve::Exponential);
    QCOMPARE(c.exponent, 3.0);
    QVERIFY(c.captured);
    QVERIFY(wizard->previewValue() < -0.1 && wizard->previewValue() > -0.5);
    QCOMPARE(wizard->previewValue(), c.apply(51.0));
    QCOMPARE(wizard->previewValueBar()->value(), wizard->previewValue());
    QCOMPARE(wizard->curvePlot()->calibration(), c);
    QVERIFY(wizard->grab().save(screenshotPath("station_wizard_settings_en.png")));

    QSignalSpy dirty(rig.page.get(), &StationPage::dirtyChanged);
    wizard->button(QWizard::FinishButton)->click();
    QTRY_VERIFY(!guard);  // closed and deleted
    QVERIFY(rig.page->isDirty());
    QCOMPARE(dirty.count(), 1);
    const trainer::ChannelCalibration* mine = rig.page->profile().calibration("gamepad", 0);
    QVERIFY(mine);
    QCOMPARE(*mine, c);
    const trainer::StationProfile engine = rig.engineProfile();
    QVERIFY(engine.calibration("gamepad", 0));
    QCOMPARE(*engine.calibration("gamepad", 0), c);

    // the channel now reads through it
    rig.pad->setAxis(0, 51);
    rig.step();
    QCOMPARE(rig.page->channelPanel()->flagLabel(0)->text(), QString());
    QCOMPARE(rig.page->channelPanel()->valueBar(0)->value(), c.apply(51.0));

    // "this device only" keeps it under the id
    wizard = rig.page->calibrate(1);
    QVERIFY(wizard);
    wizard->setLiveInput(false);
    wizard->setRestReadings(1);
    wizard->addReading(0);
    wizard->next();
    for (double raw : {50.0, -50.0}) wizard->addReading(raw);
    wizard->next();
    wizard->thisDeviceRadio()->setChecked(true);
    QCOMPARE(wizard->deviceMatch(), QStringLiteral("sdl:0300fake"));
    wizard->accept();
    QVERIFY(rig.engineProfile().calibration("sdl:0300fake", 1));
    QVERIFY(rig.engineProfile().calibration("sdl:0300fake", 1)->captured);
}

void StationTest::wizardOnATrigger()
{
    // a trigger rests at its minimum: one-sided, 0 … 1
    trainer::DeviceInfo info;
    info.id = "sdl:trigger";
    info.name = "Trigger";
    info.kind = trainer::DeviceKind::Joystick;
    info.axes.append({"trigger", 0, 0, 1000});
    CalibrationWizard wizard(nullptr, info, false, 0, trainer::ChannelCalibration{0, 0, 1000});
    QVERIFY(!wizard.liveInput());
    wizard.setRestReadings(3);
    wizard.show();
    QVERIFY(QTest::qWaitForWindowExposed(&wizard));
    QVERIFY(wizard.thisDeviceRadio()->isChecked());  // not a gamepad: this device
    for (int i = 0; i < 3; ++i) wizard.addReading(5);
    wizard.next();
    for (double raw : {5.0, 500.0, 990.0, 5.0}) wizard.addReading(raw);
    QVERIFY(wizard.button(QWizard::NextButton)->isEnabled());
    wizard.next();
    const trainer::ChannelCalibration c = wizard.calibration();
    QCOMPARE(c.rawCentre, 5.0);
    QCOMPARE(c.rawMin, 5.0);
    QCOMPARE(c.rawMax, 990.0);
    QCOMPARE(c.apply(990.0), 1.0);
    QCOMPARE(c.apply(5.0), 0.0);
    QVERIFY(wizard.grab().save(screenshotPath("station_wizard_trigger_en.png")));
}

// Issue 25, item 3: keys are digital and their presses never reach a wizard (it is
// modal, the keys go to the 3D view): a keyboard channel offers no calibration but says
// why, and offers the ramp that shapes a key's command; a gamepad's channel still
// calibrates, from live readings.
void StationTest::keyboardChannelsOfferARampNotTheWizard()
{
    for (const QString& lang : QStringList{"en", "es"}) {
        QVERIFY(i18n::install(lang));
        Rig rig;
        auto keys = std::make_shared<trainer::KeyboardDevice>(QStringList{"Q / A", "W / S"});
        rig.station.post([keys](trainer::StationEngine& e) { e.addDevice(keys); });
        rig.page->resize(1280, 720);
        rig.page->show();
        QVERIFY(QTest::qWaitForWindowExposed(rig.page.get()));
        rig.step();
        rig.page->selectDevice("keyboard");
        rig.step();
        studio::ChannelPanel* panel = rig.page->channelPanel();
        QCOMPARE(panel->channelCount(), 2);
        QVERIFY(!panel->calibrateButton(0) && !panel->calibrateButton(1));
        QVERIFY(!rig.page->calibrate(0));  // no wizard for a key
        QVERIFY(panel->keyboardNote()->isVisibleTo(rig.page.get()));
        QVERIFY2(panel->keyboardNote()->text().contains(lang == "en" ? "Keys are digital" : "Las teclas son digitales"),
                 qPrintable(panel->keyboardNote()->text()));
        QVERIFY(panel->rampSpin(0));
        QTRY_VERIFY(panel->rampSpin(0)->isVisibleTo(rig.page.get()));
        QCOMPARE(panel->rampSpin(0)->value(), 0.0);  // at once by default
        // a ramp of 0.5 s: kept in the profile as the channel's low-pass, and the key's
        // command rises to 95 % in about that time instead of at once
        panel->rampSpin(0)->setValue(0.5);
        const trainer::ChannelCalibration* c = rig.page->profile().calibration("keyboard", 0);
        QVERIFY(c);
        QCOMPARE(c->filterHz, studio::ChannelPanel::rampFilterHz(0.5));
        QVERIFY(rig.page->isDirty());
        rig.step(5);
        keys->setKeys(0, true, false);
        rig.step(100);
        const double early = panel->valueBar(0)->value();
        QVERIFY2(early > 0.2 && early < 0.6, qPrintable(QString::number(early)));
        rig.step(400);
        QVERIFY2(panel->valueBar(0)->value() > 0.94, qPrintable(QString::number(panel->valueBar(0)->value())));
        QTest::qWait(50);
        QVERIFY(rig.page->grab().save(screenshotPath("station_keyboard_ramp_" + lang + ".png")));
        keys->setKeys(0, false, false);

        // the gamepad's channels calibrate as before: the wizard takes live readings
        rig.page->selectDevice("sdl:0300fake");
        rig.step();
        QVERIFY(!panel->keyboardNote()->isVisibleTo(rig.page.get()));
        QVERIFY(panel->calibrateButton(0) && !panel->rampSpin(0));
        panel->calibrateButton(0)->click();
        QTRY_VERIFY(rig.page->findChild<CalibrationWizard*>());
        CalibrationWizard* wizard = rig.page->findChild<CalibrationWizard*>();
        QVERIFY(wizard->liveInput());
        wizard->setRestReadings(3);
        QAbstractButton* next = wizard->button(QWizard::NextButton);
        QTRY_VERIFY(next->isEnabled());  // the lever at rest, read from the station
        wizard->next();
        for (int raw : {60, 100, -90, 0}) {
            rig.pad->setAxis(0, raw);
            rig.step();
            QTRY_COMPARE(wizard->lastReading(), double(raw));
        }
        QTRY_VERIFY(next->isEnabled());
        wizard->reject();
    }
    QVERIFY(i18n::install("en"));
}

// Issue 25, item 10: a gamepad's axes and buttons are read by SDL's game-controller
// names, translated, in the mapping table, the banks and the channel lamps — not "Axis
// 0" and "9" — whether the pad is connected or not.
void StationTest::gamepadControlsAreNamed()
{
    for (const QString& lang : QStringList{"en", "es"}) {
        QVERIFY(i18n::install(lang));
        const bool en = lang == "en";
        Rig rig(true, 6, 15, true);  // a gamepad as SDL shows it
        QVERIFY(rig.page->loadProfile("Gamepad"));
        rig.page->resize(1500, 900);
        rig.page->show();
        QVERIFY(QTest::qWaitForWindowExposed(rig.page.get()));
        rig.step();
        MappingTable* table = rig.page->mappingTable();
        int leftY = -1;
        for (int r = 0; r < table->rowCount(); ++r)
            if (table->mapping(r).axis == trainer::gamepad::LeftY && table->bankOf(r) == 0) leftY = r;
        QVERIFY(leftY >= 0);
        QCOMPARE(table->axisCombo(leftY)->currentText(), en ? QStringLiteral("Left stick Y") : QStringLiteral("Stick izquierdo Y"));
        QCOMPARE(table->axisCombo(leftY)->count(), 6);
        QCOMPARE(table->selectButtonSpin(0)->text(), en ? QStringLiteral("none") : QStringLiteral("ninguno"));
        table->selectDeviceCombo(0)->setCurrentText("gamepad");
        table->selectButtonSpin(0)->setValue(trainer::gamepad::LeftShoulder);
        QCOMPARE(table->selectButtonSpin(0)->text(), en ? QStringLiteral("Left shoulder") : QStringLiteral("Hombro izquierdo"));
        QCOMPARE(table->nextBankButtonSpin()->text(), en ? QStringLiteral("Right shoulder") : QStringLiteral("Hombro derecho"));
        // typed by name, kept as SDL's index
        table->selectDeviceCombo(1)->setCurrentText("gamepad");
        table->selectButtonSpin(1)->selectAll();
        QTest::keyClicks(table->selectButtonSpin(1), "Y");
        table->selectButtonSpin(1)->interpretText();
        QCOMPARE(table->selectButtonSpin(1)->value(), int(trainer::gamepad::Y));
        QCOMPARE(rig.page->profile().banks[1].select.value(0).button, int(trainer::gamepad::Y));
        // the channels and lamps
        studio::ChannelPanel* panel = rig.page->channelPanel();
        QVERIFY2(panel->lamp(trainer::gamepad::LeftShoulder)->toolTip().endsWith(": " + trainer::gamepadButtonName(9)),
                 qPrintable(panel->lamp(trainer::gamepad::LeftShoulder)->toolTip()));
        const QList<QLabel*> labels = panel->findChildren<QLabel*>();
        QVERIFY(std::any_of(labels.begin(), labels.end(), [](QLabel* l) {
            return l->text() == trainer::gamepadAxisName(trainer::gamepad::RightTrigger);
        }));
        QTest::qWait(50);
        QVERIFY(rig.page->grab().save(screenshotPath("station_gamepad_names_" + lang + ".png")));
        // unplugged: still by name (the profile's "gamepad")
        rig.pad->setStatus(trainer::DeviceStatus::Disconnected);
        rig.step();
        QCOMPARE(table->selectButtonSpin(0)->text(), trainer::gamepadButtonName(trainer::gamepad::LeftShoulder));
        QCOMPARE(table->axisCombo(leftY)->currentText(), trainer::gamepadAxisName(trainer::gamepad::LeftY));
    }
    QVERIFY(i18n::install("en"));
}

// ---- mapping and banks -------------------------------------------------------------

void StationTest::mappingTableDrivesTheCommand()
{
    Rig rig;
    QVERIFY(rig.page->newProfile("Mapped"));
    rig.step();
    MappingTable* table = rig.page->mappingTable();
    QCOMPARE(table->rowCount(), 0);
    const int row = table->addMapping();
    QCOMPARE(row, 0);
    QCOMPARE(table->bankOf(0), 0);
    QCOMPARE(table->mapping(0).device, QStringLiteral("gamepad"));  // the pad present
    QCOMPARE(table->driveCombo(0)->count(), 9);
    QCOMPARE(table->driveCombo(0)->itemText(1), QStringLiteral("C 2 LEVANTE PLUMA"));
    QCOMPARE(table->axisCombo(0)->count(), 6);  // a gamepad's axes, by SDL's names
    QCOMPARE(table->axisCombo(0)->itemText(1), QStringLiteral("Left stick Y"));

    table->axisCombo(0)->setCurrentIndex(1);
    table->driveCombo(0)->setCurrentIndex(table->driveCombo(0)->findData(3));
    table->gainSpin(0)->setValue(0.5);
    table->signCombo(0)->setCurrentIndex(1);
    QVERIFY(rig.page->isDirty());
    const trainer::Mapping expected{"gamepad", 1, 3, 0.5, -1};
    QCOMPARE(rig.page->profile().banks.value(0).mappings.value(0), expected);
    QCOMPARE(rig.engineProfile().banks.value(0).mappings.value(0), expected);

    // at the centre it arms; then the command follows the lever
    rig.step();
    QCOMPARE(table->liveText(0), QStringLiteral("0.00"));
    rig.pad->setAxis(1, 100);
    rig.step();
    QCOMPARE(rig.commands()[2], -0.5);
    QCOMPARE(table->liveText(0), QStringLiteral("−0.50"));
    rig.pad->setAxis(1, -40);
    rig.step();
    QCOMPARE(rig.commands()[2], 0.2);
    QCOMPARE(rig.page->shownState()->commands[2], 0.2);

    // an edit re-installs the profile: a lever held off-centre waits for the centre
    table->gainSpin(0)->setValue(1.0);
    rig.step();
    QCOMPARE(rig.commands()[2], 0.0);
    QCOMPARE(table->liveText(0), QStringLiteral("waiting for centre"));
    QVERIFY(rig.page->warningsLabel()->text().contains("C 3 EXTENSIÓN"));
    rig.pad->setAxis(1, 0);
    rig.step();
    rig.pad->setAxis(1, -40);
    rig.step();
    QCOMPARE(rig.commands()[2], 0.4);

    // the wheel over a cell that has no focus scrolls the table, never edits the gain
    {
        QDoubleSpinBox* gain = table->gainSpin(0);
        gain->clearFocus();
        const QPointF at(gain->width() / 2.0, gain->height() / 2.0);
        QWheelEvent wheel(at, gain->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(gain, &wheel);
        QCOMPARE(gain->value(), 1.0);
    }

    // an "always" mapping on the keyboard's channel, then removed
    const int second = table->addMapping();
    table->bankCombo(second)->setCurrentIndex(0);  // Always
    table->deviceCombo(second)->setCurrentText("keyboard");
    QCOMPARE(rig.engineProfile().always.size(), 1);
    QCOMPARE(rig.engineProfile().always.first().device, QStringLiteral("keyboard"));
    table->removeMapping(second);
    QCOMPARE(rig.engineProfile().always.size(), 0);
    QCOMPARE(table->rowCount(), 1);
}

void StationTest::mappingToAMissingDriveShowsItsIssue()
{
    Rig rig;
    trainer::StationProfile odd;
    odd.name = "Odd";
    odd.banks.append({"Only", {}, {{"gamepad", 0, 42, 1.0, 1}, {"gamepad", 1, 2, 1.0, 1}}});
    QVERIFY(trainer::ProfileStore(rig.userRoot).save(rig.modelPath, odd, trainer::ProfileStore::SaveMode::CreateOnly));
    rig.page->setModel(rig.modelPath, linerDrives(), "Odd");
    rig.step();
    MappingTable* table = rig.page->mappingTable();
    QCOMPARE(table->rowCount(), 2);
    QVERIFY(table->issueText(0).contains("not in this model"));
    QVERIFY(table->liveText(0).contains("not in this model"));
    QVERIFY(table->issueText(1).isEmpty());
    QCOMPARE(table->driveCombo(0)->currentText(), QStringLiteral("C 42 (not in this model)"));
    QListWidget* issues = rig.page->issuesList();
    QVERIFY(issues->isVisibleTo(rig.page.get()));
    QCOMPARE(issues->count(), 1);
    QVERIFY(issues->item(0)->text().contains("banks[0].mappings[0]"));
    QVERIFY(issues->item(0)->text().startsWith("Warning"));
    // choosing a real drive clears it
    table->driveCombo(0)->setCurrentIndex(table->driveCombo(0)->findData(5));
    rig.step();
    QVERIFY(table->issueText(0).isEmpty());
    QVERIFY(!issues->isVisibleTo(rig.page.get()));
}

void StationTest::bankBannerFollowsABankSwitch()
{
    Rig rig;
    QVERIFY(rig.page->newProfile("Banks"));
    MappingTable* table = rig.page->mappingTable();
    table->renameBank(0, "Boom");
    QCOMPARE(table->addBank("Wrist"), 1);
    QCOMPARE(table->bankCount(), 2);
    table->selectDeviceCombo(0)->setCurrentText("gamepad");
    table->selectButtonSpin(0)->setValue(0);
    table->selectDeviceCombo(1)->setCurrentText("gamepad");
    table->selectButtonSpin(1)->setValue(1);
    table->nextBankDeviceCombo()->setCurrentText("gamepad");
    table->nextBankButtonSpin()->setValue(5);
    const trainer::StationProfile p = rig.engineProfile();
    QCOMPARE(p.banks.size(), 2);
    QCOMPARE(p.banks[0].name, QStringLiteral("Boom"));
    QCOMPARE(p.banks[1].select.value(0), (trainer::ButtonRef{"gamepad", 1}));
    QCOMPARE(p.nextBank, (trainer::ButtonRef{"gamepad", 5}));
    // a mapping in each bank, on the same axis
    int r = table->addMapping();
    table->driveCombo(r)->setCurrentIndex(table->driveCombo(r)->findData(1));
    r = table->addMapping();
    table->bankCombo(r)->setCurrentIndex(table->bankCombo(r)->findData(1));
    table->driveCombo(r)->setCurrentIndex(table->driveCombo(r)->findData(4));
    QCOMPARE(rig.engineProfile().banks[1].mappings.size(), 1);

    rig.step();
    // with how the connected pad switches them, its buttons by name
    const QString hint = QStringLiteral("\nGuide: next bank · A: Boom · B: Wrist");
    QCOMPARE(rig.page->bankLabel()->text(), QStringLiteral("Bank: Boom (1 of 2)") + hint);
    QCOMPARE(table->liveText(1), QStringLiteral("bank not active"));
    rig.press(1);
    QCOMPARE(rig.page->bankLabel()->text(), QStringLiteral("Bank: Wrist (2 of 2)") + hint);
    QCOMPARE(table->liveText(0), QStringLiteral("bank not active"));
    rig.pad->setAxis(0, 100);
    rig.step();
    QCOMPARE(rig.commands()[3], 1.0);
    QCOMPARE(rig.commands()[0], 0.0);
    // an edit keeps the active bank
    table->gainSpin(1)->setValue(0.5);
    rig.step();
    QCOMPARE(rig.page->bankLabel()->text(), QStringLiteral("Bank: Wrist (2 of 2)") + hint);
    rig.pad->setAxis(0, 0);
    rig.press(5);  // next bank: round to the first
    QCOMPARE(rig.page->bankLabel()->text(), QStringLiteral("Bank: Boom (1 of 2)") + hint);

    // removing a bank with mappings asks
    rig.page->answers = {false};
    QVERIFY(!table->removeBank(1));
    QCOMPARE(table->bankCount(), 2);
    rig.page->answers = {true};
    QVERIFY(table->removeBank(1));
    QCOMPARE(rig.engineProfile().banks.size(), 1);
    QCOMPARE(table->rowCount(), 1);
    rig.step();
    QCOMPARE(rig.page->bankLabel()->text(), QStringLiteral("Bank: Boom"));
}

// ---- serial consoles, record and replay -------------------------------------------

void StationTest::serialConsoleIsAddedAndRemoved()
{
    {
        studio::SerialConsoleDialog dialog;
        QVERIFY(dialog.portCombo()->isEditable());
        QCOMPARE(dialog.baud(), 115200);
        QCOMPARE(dialog.baudCombo()->itemText(0), QStringLiteral("9600"));
        QCOMPARE(dialog.baudCombo()->itemText(dialog.baudCombo()->count() - 1), QStringLiteral("921600"));
        dialog.portCombo()->setCurrentText("/dev/ttyACM7");
        dialog.baudCombo()->setCurrentIndex(3);
        QCOMPARE(dialog.setting(), (trainer::DeviceSetting{"serial:/dev/ttyACM7", 57600}));
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));  // (its screenshots: screenshots())
    }
    Rig rig;
    QVERIFY(rig.page->newProfile("Console"));
    const QString port = rig.dir.filePath("no-such-port");
    rig.page->serial = trainer::DeviceSetting{"serial:" + port, 57600};
    QVERIFY(rig.page->addSerialConsole());
    QCOMPARE(rig.page->profile().devices.size(), 1);
    QCOMPARE(rig.engineProfile().devices.value(0), (trainer::DeviceSetting{"serial:" + port, 57600}));
    rig.step();
    QTreeWidgetItem* row = deviceRow(rig.page->devicesList(), "serial:" + port);
    QVERIFY(row);
    QVERIFY2(!row->text(StationPage::StatusColumn).startsWith("Connected"), qPrintable(row->text(StationPage::StatusColumn)));
    QCOMPARE(rig.page->selectedDeviceId(), "serial:" + port);
    QVERIFY(rig.page->removeDeviceButton()->isEnabled());
    rig.page->resize(1500, 900);
    rig.page->show();
    QVERIFY(QTest::qWaitForWindowExposed(rig.page.get()));
    QVERIFY(rig.page->grab().save(screenshotPath("station_page_serial_en.png")));
    QVERIFY(rig.page->removeSelectedDevice());
    QVERIFY(rig.page->profile().devices.isEmpty());
    QVERIFY(rig.engineProfile().devices.isEmpty());
    rig.step();
    QVERIFY(!deviceRow(rig.page->devicesList(), "serial:" + port));
    // cancelled, and a bad id
    rig.page->serial.reset();
    QVERIFY(!rig.page->addSerialConsole());
    QVERIFY(!rig.page->addSerialConsole({"comedi:/dev/comedi0", 0}));
    QCOMPARE(rig.page->told.size(), 1);
}

void StationTest::recordAndReplay()
{
    Rig rig;
    QVERIFY(rig.page->loadProfile("Gamepad"));
    const QString log = rig.dir.filePath("input.log");
    rig.page->saveFile = log;
    QVERIFY(rig.page->startRecording());
    QVERIFY(rig.page->isRecording());
    QCOMPARE(rig.page->recordButton()->text(), QStringLiteral("Stop recording"));
    for (int i = 0; i <= 20; ++i) {
        rig.pad->setAxis(1, 5.0 * i);
        rig.step(5);
    }
    QVERIFY(rig.page->stopRecording());
    QVERIFY(!rig.page->isRecording());
    QVERIFY(readAll(log).contains("#device 0"));

    rig.page->openFile = log;
    QVERIFY(rig.page->startReplay());
    QVERIFY(rig.page->isReplaying());
    QCOMPARE(rig.page->replayButton()->text(), QStringLiteral("Stop replay"));
    rig.step(50);
    QCOMPARE(rig.page->devicesList()->topLevelItemCount(), 2);
    QVERIFY(rig.page->devicesList()->topLevelItem(1)->text(StationPage::NameColumn).contains("(replay) · sdl:0300fake"));
    QVERIFY(rig.page->warningsLabel()->text().contains("Replaying input.log"));
    rig.page->stopReplay();
    rig.step();
    QCOMPARE(rig.page->devicesList()->topLevelItemCount(), 1);
    QVERIFY(!rig.page->warningsLabel()->text().contains("Replaying"));

    // a file that is not a log
    const QString bad = rig.dir.filePath("bad.log");
    QVERIFY(writeFile(bad, "hello\n"));
    QVERIFY(!rig.page->startReplay(bad));
    QCOMPARE(rig.page->told.size(), 1);
}

// ---- a started station, as in the application ---------------------------------------

void StationTest::runningStationFollowsTheLever()
{
    QTemporaryDir dir;
    trainer::Station station;
    auto pad = std::make_shared<FakeDevice>("sdl:running", trainer::DeviceKind::Gamepad, 4, 6, -32768, 0, 32767,
                                            "Running Pad");
    station.start(false);
    station.call([pad](trainer::StationEngine& e) {
        e.setDrives(9, linerDrives());
        e.addDevice(pad);
    });
    TestPage page(&station);
    page.setProfileStore(trainer::ProfileStore(dir.filePath("user")));
    page.setModel(dir.filePath("liner_manipulator.pad"), linerDrives());  // no profiles: the default
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    QTRY_VERIFY(page.shownState() && page.shownState()->devices.size() == 1);
    QTRY_COMPARE(page.channelPanel()->channelCount(), 4);
    // the default profile: 9 keyboard rows (always), then bank 1 where the left stick's y
    // drives C 2 with sign −1 (forward is −y in SDL)
    QTRY_COMPARE(page.mappingTable()->liveText(10), QStringLiteral("0.00"));
    QCOMPARE(page.mappingTable()->mapping(10), (trainer::Mapping{"gamepad", 1, 2, 1.0, -1}));
    station.call([pad](trainer::StationEngine&) { pad->setAxis(1, -32768); });
    QTRY_COMPARE(page.channelPanel()->valueBar(1)->value(), -1.0);
    QTRY_VERIFY(page.shownState()->commands[1] > 0.99);
    QTRY_COMPARE(page.mappingTable()->liveText(10), QStringLiteral("+1.00"));
    station.call([pad](trainer::StationEngine&) { pad->setAxis(1, 0); });
    QTRY_COMPARE(page.shownState()->commands[1], 0.0);
    station.stop();
}

// the shipped profiles carry their texts in Spanish ("translations"): the name in the
// list, the description, the banks in the table and the banner; the keyboard is
// "Teclado" after a switch at run time; a button spin box's "ninguno" is shown whole
// (it was cut to "guno"), in the banks table and as the next-bank button
void StationTest::shippedProfileAndKeyboardReadInSpanish()
{
    Rig rig(false);
    const QString shipped = rig.dir.filePath("models/liner_manipulator.station/gamepad.json");
    QVERIFY(writeFile(shipped, readAll(QStringLiteral(PADROB_SOURCE_DIR) + "/models/liner_manipulator.station/gamepad.json")));
    rig.station.post([](trainer::StationEngine& e) { e.addDevice(std::make_shared<trainer::KeyboardDevice>(QStringList{"Q / A"})); });
    rig.page->setModel(rig.modelPath, linerDrives());
    QVERIFY(rig.page->loadProfile("Gamepad"));
    rig.page->resize(1280, 720);
    rig.page->show();
    QVERIFY(QTest::qWaitForWindowExposed(rig.page.get()));
    rig.step();
    QCOMPARE(rig.page->profileCombo()->currentText(), QStringLiteral("Gamepad (shipped)"));
    QVERIFY(rig.page->descriptionLabel()->text().startsWith("A common two-stick gamepad"));
    QVERIFY2(rig.page->bankLabel()->text().contains("Boom"), qPrintable(rig.page->bankLabel()->text()));

    QVERIFY(i18n::install("es"));
    studio::test::settle(100);
    rig.step();
    QCOMPARE(rig.page->profileCombo()->currentText(), QStringLiteral("Mando (incluido)"));
    QCOMPARE(rig.page->profile().name, QStringLiteral("Gamepad"));  // (its identity)
    QVERIFY2(rig.page->descriptionLabel()->text().startsWith("Un mando común de dos palancas"),
             qPrintable(rig.page->descriptionLabel()->text()));
    QVERIFY2(rig.page->bankLabel()->text().contains("Pluma"), qPrintable(rig.page->bankLabel()->text()));
    MappingTable* table = rig.page->mappingTable();
    QCOMPARE(table->banksTable()->item(0, MappingTable::BankNameColumn)->text(), QStringLiteral("Pluma"));
    QCOMPARE(table->banksTable()->item(1, MappingTable::BankNameColumn)->text(), QStringLiteral("Muñeca"));
    QTreeWidgetItem* keyboard = deviceRow(rig.page->devicesList(), "keyboard");
    QVERIFY(keyboard);
    QVERIFY2(keyboard->text(StationPage::NameColumn).startsWith("Teclado"), qPrintable(keyboard->text(StationPage::NameColumn)));
    // "ninguno" whole
    const int bank = table->addBank("Extra");
    studio::test::settle(100);
    QSpinBox* select = table->selectButtonSpin(bank);
    QCOMPARE(select->text(), QStringLiteral("ninguno"));
    QVERIFY2(table->banksTable()->columnWidth(MappingTable::SelectButtonColumn) >= select->sizeHint().width() &&
                 select->width() >= select->sizeHint().width(),
             qPrintable(QStringLiteral("%1 px for %2").arg(select->width()).arg(select->sizeHint().width())));
    QSpinBox* next = table->nextBankButtonSpin();
    next->setValue(-1);
    QCOMPARE(next->text(), QStringLiteral("ninguno"));
    QVERIFY2(next->width() >= next->sizeHint().width(),
             qPrintable(QStringLiteral("%1 px for %2").arg(next->width()).arg(next->sizeHint().width())));
    QVERIFY(rig.page->grab().save(studio::test::screenshotPath("station_shipped_profile_es.png")));

    QVERIFY(i18n::install("en"));
    studio::test::settle(100);
    rig.step();
    QCOMPARE(rig.page->profileCombo()->currentText().left(17), QStringLiteral("Gamepad (shipped)"));
    QVERIFY(rig.page->bankLabel()->text().contains("Boom"));
    QVERIFY(deviceRow(rig.page->devicesList(), "keyboard")->text(StationPage::NameColumn).startsWith("Keyboard"));
}

// ---- screenshots ------------------------------------------------------------------

// ---- the language at run time -----------------------------------------------------

void StationTest::languageSwitchesAtRunTime()
{
    Rig rig;
    QVERIFY(rig.page->newProfile("Blank"));  // no calibrations: "not calibrated"
    rig.page->resize(1500, 900);
    rig.page->show();
    QVERIFY(QTest::qWaitForWindowExposed(rig.page.get()));
    MappingTable* table = rig.page->mappingTable();
    table->addMapping();
    table->gainSpin(0)->setValue(1.25);
    rig.pad->setAxis(0, 50);
    rig.step(5);
    studio::ChannelPanel* panel = rig.page->channelPanel();
    auto* mappingBox = qobject_cast<QGroupBox*>(table->parentWidget());
    QVERIFY(mappingBox);
    QCOMPARE(mappingBox->title(), QStringLiteral("Valve mapping"));
    QCOMPARE(rig.page->recordButton()->text(), QStringLiteral("Record input…"));
    QCOMPARE(panel->flagLabel(0)->text(), QStringLiteral("not calibrated"));
    QCOMPARE(panel->valueLabel(0)->text(), QStringLiteral("+0.50"));
    QCOMPARE(table->table()->horizontalHeaderItem(MappingTable::BankColumn)->text(), QStringLiteral("Bank"));
    QCOMPARE(deviceRow(rig.page->devicesList(), "sdl:0300fake")->text(StationPage::StatusColumn),
             QStringLiteral("Connected"));
    const QString gainEn = table->gainSpin(0)->text();
    QVERIFY2(gainEn.contains('.'), qPrintable(gainEn));

    // to Spanish, without a restart: the texts, and numbers with a decimal comma
    QVERIFY(i18n::install("es"));
    studio::test::settle(100);
    rig.step();
    QCOMPARE(mappingBox->title(), QStringLiteral("Asignación de válvulas"));
    QCOMPARE(rig.page->recordButton()->text(), QStringLiteral("Grabar entradas…"));
    QCOMPARE(panel->flagLabel(0)->text(), QStringLiteral("sin calibrar"));
    QCOMPARE(panel->valueLabel(0)->text(), QStringLiteral("+0,50"));
    QCOMPARE(panel->calibrateButton(0)->text(), QStringLiteral("Calibrar…"));
    QCOMPARE(table->table()->horizontalHeaderItem(MappingTable::BankColumn)->text(), QStringLiteral("Banco"));
    QCOMPARE(deviceRow(rig.page->devicesList(), "sdl:0300fake")->text(StationPage::StatusColumn),
             QStringLiteral("Conectado"));
    QVERIFY2(rig.page->bankLabel()->text().startsWith(QStringLiteral("Banco")), qPrintable(rig.page->bankLabel()->text()));
    const QString gainEs = table->gainSpin(0)->text();
    QCOMPARE(gainEs, QString(gainEn).replace('.', ','));
    // the spin box reads what it shows: a gain typed with a comma
    QCOMPARE(table->gainSpin(0)->valueFromText(QStringLiteral("0,75")), 0.75);

    // and back
    QVERIFY(i18n::install("en"));
    studio::test::settle(100);
    rig.step();
    QCOMPARE(mappingBox->title(), QStringLiteral("Valve mapping"));
    QCOMPARE(panel->valueLabel(0)->text(), QStringLiteral("+0.50"));
    QCOMPARE(table->gainSpin(0)->text(), gainEn);
}

// ---- screenshots ------------------------------------------------------------------

void StationTest::screenshots()
{
    for (const QString& lang : QStringList{"en", "es"}) {
        QVERIFY(i18n::install(lang));
        const QString suffix = "_" + lang + ".png";
        {
            Rig rig(true, 6, 15, true);  // a gamepad as SDL shows it
            QVERIFY(rig.page->loadProfile("Gamepad"));
            rig.page->resize(1500, 900);
            rig.page->show();
            QVERIFY(QTest::qWaitForWindowExposed(rig.page.get()));
            // the second bank, a few levers moved, one button held, one lever waiting
            rig.press(trainer::gamepad::RightShoulder);
            rig.pad->setAxis(0, 12000);
            rig.pad->setAxis(1, -20000);
            rig.pad->setAxis(4, 30000);
            rig.pad->setButton(trainer::gamepad::A, true);
            rig.step(5);
            rig.pad->setAxis(2, 26000);  // moved after the switch: armed; held since: waits
            rig.step(5);
            trainer::ChannelCalibration c{-32100, 120, 32500, 0.08, 0.06};
            c.captured = true;
            rig.page->applyCalibration("gamepad", 0, c);
            rig.step(5);
            QTest::qWait(50);
            QVERIFY(rig.page->grab().save(screenshotPath("station_page" + suffix)));

            // the calibration wizard, each page
            CalibrationWizard* wizard = rig.page->calibrate(1);
            QVERIFY(wizard);
            wizard->setLiveInput(false);
            wizard->setRestReadings(5);
            QVERIFY(QTest::qWaitForWindowExposed(wizard));
            for (double raw : {-120.0, -80.0, -150.0, -100.0, -110.0}) wizard->addReading(raw);
            QTest::qWait(50);
            QVERIFY(wizard->grab().save(screenshotPath("station_wizard_rest" + suffix)));
            wizard->next();
            for (double raw : {-100.0, 9000.0, 31000.0, 12000.0, -30500.0, -4000.0}) wizard->addReading(raw);
            QTest::qWait(50);
            QVERIFY(wizard->grab().save(screenshotPath("station_wizard_travel" + suffix)));
            wizard->next();
            wizard->deadBandLowSpin()->setValue(6.5);
            wizard->deadBandHighSpin()->setValue(6.5);
            wizard->curveCombo()->setCurrentIndex(1);
            wizard->exponentSpin()->setValue(2.5);
            wizard->filterSpin()->setValue(12.5);
            wizard->addReading(14000.0);
            QTest::qWait(50);
            QVERIFY(wizard->grab().save(screenshotPath("station_wizard_settings" + suffix)));
            if (lang == QLatin1String("es")) {
                // a decimal comma in the spin boxes and in the readings
                QVERIFY2(wizard->exponentSpin()->text().contains(QStringLiteral("2,50")),
                         qPrintable(wizard->exponentSpin()->text()));
                QVERIFY2(wizard->filterSpin()->text().contains(QStringLiteral("12,5")),
                         qPrintable(wizard->filterSpin()->text()));
            }
            wizard->reject();

            // a device gone, a missing drive: the warnings
            trainer::StationProfile odd = rig.page->profile();
            odd.banks[0].mappings.append({"gamepad", 3, 42, 1.0, 1});
            odd.name = "With problems";
            QVERIFY(trainer::ProfileStore(rig.userRoot).save(rig.modelPath, odd, trainer::ProfileStore::SaveMode::CreateOnly));
            rig.page->setModel(rig.modelPath, linerDrives(), "With problems");
            rig.pad->setStatus(trainer::DeviceStatus::Disconnected);
            rig.step(5);
            QTest::qWait(50);
            QVERIFY(rig.page->grab().save(screenshotPath("station_page_warnings" + suffix)));
        }
        {
            studio::SerialConsoleDialog dialog;
            dialog.portCombo()->setCurrentText("/dev/serial/by-id/usb-Padrob_DAQ_0042-if00");
            dialog.show();
            QVERIFY(QTest::qWaitForWindowExposed(&dialog));
            QTest::qWait(50);
            QVERIFY(dialog.grab().save(screenshotPath("station_serial_dialog" + suffix)));
        }
    }
    QVERIFY(i18n::install("en"));
}

QTEST_MAIN(StationTest)
#include "station_test.moc"
