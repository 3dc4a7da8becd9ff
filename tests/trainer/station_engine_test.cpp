// The station engine with hand-set devices: calibration → mapping → banks →
// commands; arming at the centre; disconnection holds the drives; replay-only mode;
// recording.
#include "fake_device.h"

#include "trainer/input/input_log.h"
#include "trainer/input/keyboard_device.h"
#include "trainer/station/station_engine.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace trainer;
using test::FakeDevice;

namespace {

QList<DriveInfo> drives()
{
    // tree joints 0…3; joint ids 1…4 (tree joint 1 is not a drive here: ids 1,3,4,5)
    return {{0, 1, "GIRO"}, {2, 3, "EXT"}, {3, 4, "MUÑECA"}, {4, 5, "ROT"}};
}

struct Rig {
    StationEngine engine;
    std::shared_ptr<FakeDevice> pad = std::make_shared<FakeDevice>("sdl:pad1", DeviceKind::Gamepad, 4, 6);
    double t = 0.0;

    Rig()
    {
        engine.setDrives(5, drives());
        engine.addDevice(pad);
    }
    const std::vector<double>& step(int n = 1)
    {
        for (int i = 0; i < n; ++i) engine.update(t += 1e-3);
        return engine.commands();
    }
    void press(int button)
    {
        pad->setButton(button, true);
        step();
        pad->setButton(button, false);
        step();
    }
};

StationProfile twoBanks()
{
    StationProfile p;
    p.name = "two banks";
    p.banks.append({"A", {{"gamepad", 0}}, {{"gamepad", 0, 1, 1.0, 1}, {"gamepad", 1, 3, 0.5, -1}}});
    p.banks.append({"B", {{"gamepad", 1}}, {{"gamepad", 0, 4, 1.0, 1}}});
    p.always.append({"gamepad", 3, 5, 1.0, 1});
    p.nextBank = {"gamepad", 5};
    return p;
}

}  // namespace

TEST(StationEngine, AxisThroughCalibrationAndMappingToTheDrive)
{
    Rig r;
    EXPECT_TRUE(r.engine.setProfile(twoBanks()).isEmpty());
    r.step();
    r.pad->setAxis(0, 50);   // half right → drive 1 (tree 0) +0.5
    r.pad->setAxis(1, -100);  // full back → drive 3 (tree 2) −1 · 0.5 · −1 = +0.5
    const auto& u = r.step();
    EXPECT_NEAR(u[0], 0.5, 1e-12);
    EXPECT_NEAR(u[2], 0.5, 1e-12);
    EXPECT_EQ(u[1], 0.0);
    EXPECT_EQ(u[3], 0.0);  // bank B's drive is not active
    const StationState st = r.engine.state();
    ASSERT_EQ(st.devices.size(), 1);
    EXPECT_FALSE(st.devices[0].channels[0].calibrated);  // nominal range, flagged
    EXPECT_EQ(st.bankNames, (QStringList{"A", "B"}));
}

TEST(StationEngine, ProfileCalibrationIsAppliedPerDeviceOrKind)
{
    Rig r;
    StationProfile p = twoBanks();
    ChannelCalibration c{-100, 20, 100, 0.0, 0.0, true};
    c.captured = true;
    p.setCalibration("gamepad", 0, c);
    r.engine.setProfile(p);
    r.pad->setAxis(0, 20);  // this lever rests at 20
    r.step();
    r.pad->setAxis(0, 60);  // halfway from 20 to 100, inverted
    EXPECT_NEAR(r.step()[0], -0.5, 1e-12);
    EXPECT_TRUE(r.engine.state().devices[0].channels[0].calibrated);
    // an id beats a kind
    ChannelCalibration byId{-100, 60, 100};
    byId.captured = true;
    r.engine.setCalibration("sdl:pad1", 0, byId);
    EXPECT_EQ(r.step()[0], 0.0);
}

TEST(StationEngine, ButtonsSwitchBanksOnThePressAndTheNewLeverWaitsForTheCentre)
{
    Rig r;
    r.engine.setProfile(twoBanks());
    r.step();
    r.pad->setAxis(0, 80);
    EXPECT_NEAR(r.step()[0], 0.8, 1e-12);
    r.press(1);  // bank B while the lever is held over
    EXPECT_EQ(r.engine.activeBank(), 1);
    EXPECT_EQ(r.step()[0], 0.0);  // bank A's drive released: valve closed
    EXPECT_EQ(r.step()[3], 0.0);  // bank B's drive does not jump to 0.8
    EXPECT_TRUE(r.engine.state().warnings.join("\n").contains("MUÑECA"));
    r.pad->setAxis(0, 0);
    r.step();
    r.pad->setAxis(0, -40);
    EXPECT_NEAR(r.step()[3], -0.4, 1e-12);
    // next-bank button cycles, held does not repeat
    r.pad->setButton(5, true);
    r.step(10);
    EXPECT_EQ(r.engine.activeBank(), 0);
    r.pad->setButton(5, false);
    r.step();
    r.press(5);
    EXPECT_EQ(r.engine.activeBank(), 1);
}

TEST(StationEngine, AlwaysMappingsWorkInEveryBankAndSumsAreClamped)
{
    Rig r;
    StationProfile p = twoBanks();
    p.always.append({"gamepad", 2, 5, 1.0, 1});
    r.engine.setProfile(p);
    r.step();
    r.pad->setAxis(3, 70);
    r.pad->setAxis(2, 60);
    EXPECT_EQ(r.step()[4], 1.0);
    r.press(1);
    EXPECT_EQ(r.step()[4], 1.0);
}

TEST(StationEngine, ALeverHeldAtStartDoesNotMoveTheMachine)
{
    Rig r;
    r.pad->setAxis(0, 100);
    r.engine.setProfile(twoBanks());
    EXPECT_EQ(r.step(5)[0], 0.0);
    r.pad->setAxis(0, 1);  // within the arming threshold
    r.step();
    r.pad->setAxis(0, 30);
    EXPECT_NEAR(r.step()[0], 0.3, 1e-12);
}

TEST(StationEngine, DisconnectionClosesTheValvesWarnsAndResumesAfterCentring)
{
    Rig r;
    r.engine.setProfile(twoBanks());
    r.step();
    r.pad->setAxis(0, 90);
    EXPECT_NEAR(r.step()[0], 0.9, 1e-12);
    r.pad->setStatus(DeviceStatus::Disconnected);
    EXPECT_EQ(r.step()[0], 0.0);
    const QString warnings = r.engine.state().warnings.join("\n");
    EXPECT_TRUE(warnings.contains("GIRO")) << warnings.toStdString();
    EXPECT_TRUE(warnings.contains("unplugged"));
    r.pad->setStatus(DeviceStatus::Connected);  // back, lever still over
    EXPECT_EQ(r.step(3)[0], 0.0);
    r.pad->setAxis(0, 0);
    r.step();
    r.pad->setAxis(0, 90);
    EXPECT_NEAR(r.step()[0], 0.9, 1e-12);
    EXPECT_TRUE(r.engine.state().warnings.isEmpty());
}

TEST(StationEngine, AReadingNoLeverCanGiveIsADeviceFaultThatClosesItsValve)
{
    // a 10-bit console (0…1023) whose first lever's wire breaks: 65535, not "fully open"
    StationEngine engine;
    engine.setDrives(5, drives());
    auto box = std::make_shared<FakeDevice>("serial:/dev/ttyACM0", DeviceKind::SerialDaq, 2, 0, 0.0, 511.5, 1023.0);
    engine.addDevice(box);
    StationProfile p;
    p.name = "console";
    p.always.append({"serial:/dev/ttyACM0", 0, 1, 1.0, 1});
    p.always.append({"serial:/dev/ttyACM0", 1, 3, 1.0, 1});
    engine.setProfile(p);
    double t = 0.0;
    const auto step = [&](int n = 1) -> const std::vector<double>& {
        for (int i = 0; i < n; ++i) engine.update(t += 1e-3);
        return engine.commands();
    };
    box->setAxis(0, 511.5);
    box->setAxis(1, 511.5);
    step();
    box->setAxis(0, 1023.0);
    box->setAxis(1, 1023.0);
    EXPECT_NEAR(step()[0], 1.0, 1e-12);
    EXPECT_NEAR(step()[2], 1.0, 1e-12);
    box->setAxis(0, 65535.0);
    const std::vector<double> u = step();
    EXPECT_EQ(u[0], 0.0) << "the valve of a broken lever must close";
    EXPECT_NEAR(u[2], 1.0, 1e-12) << "the other lever still drives";
    StationState st = engine.state();
    EXPECT_TRUE(st.devices[0].channels[0].fault);
    EXPECT_FALSE(st.devices[0].channels[1].fault);
    const QString warnings = st.warnings.join("\n");
    EXPECT_TRUE(warnings.contains("device fault") && warnings.contains("65535") && warnings.contains("GIRO"))
        << warnings.toStdString();
    EXPECT_EQ(step(50)[0], 0.0);
    // sane again but held over: still closed until the lever is at the centre
    box->setAxis(0, 900.0);
    EXPECT_EQ(step(5)[0], 0.0);
    EXPECT_FALSE(engine.state().devices[0].channels[0].fault);
    box->setAxis(0, 511.5);
    step();
    box->setAxis(0, 1023.0);
    EXPECT_NEAR(step()[0], 1.0, 1e-12);
    // a reading a little past the nominal end (a worn potentiometer) is no fault
    box->setAxis(0, 1040.0);
    EXPECT_NEAR(step()[0], 1.0, 1e-12);
    EXPECT_FALSE(engine.state().devices[0].channels[0].fault);
}

TEST(StationEngine, MappingToAMissingDriveOrDeviceIsIgnoredWithAWarning)
{
    Rig r;
    StationProfile p = twoBanks();
    p.banks[0].mappings.append({"gamepad", 2, 77, 1.0, 1});
    p.banks[0].mappings.append({"joystick", 0, 4, 1.0, 1});
    const QList<ProfileIssue> issues = r.engine.setProfile(p);
    ASSERT_EQ(issues.size(), 1);
    EXPECT_FALSE(issues[0].error);
    r.step();
    r.pad->setAxis(2, 100);
    r.pad->setAxis(0, 100);
    const auto& u = r.step();
    EXPECT_EQ(u[3], 0.0);
    EXPECT_EQ(u[0], 1.0);  // the rest works
    EXPECT_TRUE(r.engine.state().setupWarnings.join("\n").contains("No Joystick found — valves closed, holding C 4 MUÑECA"))
        << r.engine.state().setupWarnings.join("\n").toStdString();
}

TEST(StationEngine, KeyboardPairsDriveOneToOne)
{
    StationEngine e;
    e.setDrives(5, drives());
    auto keys = std::make_shared<KeyboardDevice>(QStringList{"Q / A", "W / S"});
    e.addDevice(keys);
    StationProfile p;
    p.always = {{"keyboard", 0, 1, 1.0, 1}, {"keyboard", 1, 5, 1.0, 1}};
    p.banks.append({"-", {}, {}});
    e.setProfile(p);
    e.update(0.001);
    keys->setKeys(0, true, false);
    keys->setKeys(1, true, true);
    e.update(0.002);
    EXPECT_EQ(e.commands()[0], 1.0);
    EXPECT_EQ(e.commands()[4], 0.0);
    keys->setKeys(1, false, true);
    e.update(0.003);
    EXPECT_EQ(e.commands()[4], -1.0);
    EXPECT_TRUE(e.state().devices[0].channels[0].calibrated);
    keys->releaseAll();
    e.update(0.004);
    EXPECT_EQ(e.commands()[0], 0.0);
}

TEST(StationEngine, RecordedInputReplaysThroughTheSameProfile)
{
    QTemporaryDir dir;
    const QString path = dir.filePath("run.log");
    std::vector<double> live;
    {
        Rig r;
        r.engine.setProfile(twoBanks());
        InputRecorder rec;
        ASSERT_TRUE(rec.start(path, r.t));
        r.engine.setRecorder(&rec);
        r.step();
        for (int i = 0; i <= 100; ++i) {
            r.pad->setAxis(0, i % 50);
            live.push_back(r.step()[0]);
        }
        r.press(1);
        r.engine.setRecorder(nullptr);
        ASSERT_TRUE(rec.stop());
        EXPECT_GT(rec.linesWritten(), 100u);
    }
    auto log = std::make_shared<InputLog>();
    QString error;
    ASSERT_TRUE(InputLog::load(path, *log, &error)) << error.toStdString();
    ASSERT_EQ(log->devices.size(), 1);
    EXPECT_EQ(log->devices[0].id, "sdl:pad1");
    StationEngine e;
    e.setDrives(5, drives());
    auto pad = std::make_shared<FakeDevice>("sdl:pad1", DeviceKind::Gamepad, 4, 6);
    e.addDevice(pad);  // the real device is ignored while replaying
    pad->setAxis(0, 100);
    e.setReplayOnly(true);
    for (auto& d : replayDevices(log)) e.addDevice(d);
    e.setProfile(twoBanks());
    double t = 5.0;
    e.update(t);             // log time 0 (the recording started a step before the first sample)
    e.update(t += 1e-3);     // the live run's first step
    std::vector<double> replayed;
    for (int i = 0; i <= 100; ++i) replayed.push_back((e.update(t += 1e-3), e.commands()[0]));
    EXPECT_EQ(replayed, live);
    e.update(t += 1e-3);
    e.update(t += 1e-3);
    EXPECT_EQ(e.activeBank(), 1);  // the recorded button press too
}

TEST(InputLog, MalformedLogsSayWhichLine)
{
    InputLog log;
    QString error;
    EXPECT_FALSE(InputLog::parse("hello\n", log, &error));
    EXPECT_TRUE(error.startsWith("line 1"));
    const QByteArray head = "# padrob input log 1\n#device 0 {\"id\":\"keyboard\",\"kind\":\"keyboard\","
                            "\"axes\":[{\"name\":\"Q / A\",\"min\":-1,\"rest\":0,\"max\":1}],\"buttons\":[]}\n";
    EXPECT_TRUE(InputLog::parse(head + "0.5,0,1\n1.0,0,0\n", log, &error)) << error.toStdString();
    EXPECT_EQ(log.samples.size(), 2u);
    EXPECT_FALSE(InputLog::parse(head + "0.5,0,1\n0.2,0,0\n", log, &error));
    EXPECT_TRUE(error.startsWith("line 4"));
    EXPECT_FALSE(InputLog::parse(head + "0.5,0,1,1\n", log, &error));
    EXPECT_TRUE(error.startsWith("line 3"));
    EXPECT_FALSE(InputLog::parse(head + "0.5,1,1\n", log, &error));
    // an empty device field says so (not "device  is not described"); control characters
    // of a field are shown escaped, never sent raw to a terminal
    EXPECT_FALSE(InputLog::parse(head + "0.5,,1\n", log, &error));
    EXPECT_TRUE(error.contains("device number") && error.contains("missing")) << error.toStdString();
    EXPECT_FALSE(InputLog::parse(head + "0.5,\x1b[2J7,1\n", log, &error));
    EXPECT_TRUE(error.contains("\\x1b[2J7")) << error.toStdString();
    EXPECT_FALSE(error.contains(QChar(0x1b)));
    EXPECT_FALSE(InputLog::load("/nonexistent/x.log", log, &error));
    EXPECT_TRUE(error.contains("/nonexistent/x.log"));
}

TEST(InputLog, ReplayFollowsTheLogsTimingSpeedPauseAndSeek)
{
    auto log = std::make_shared<InputLog>();
    QString error;
    ASSERT_TRUE(InputLog::parse("# padrob input log 1\n#device 0 {\"id\":\"keyboard\",\"kind\":\"keyboard\","
                                "\"axes\":[{\"name\":\"k\",\"min\":-1,\"rest\":0,\"max\":1}],\"buttons\":[]}\n"
                                "0,0,0\n1,0,1\n2,0,-1\n",
                                *log, &error));
    ReplayDevice d(log, 0);
    EXPECT_TRUE(d.isReplay());
    EXPECT_EQ(d.info().id, "keyboard");
    d.poll(10.0);
    EXPECT_EQ(d.sample().axes[0], 0.0);
    d.poll(10.999);
    EXPECT_EQ(d.sample().axes[0], 0.0);
    d.poll(11.0);
    EXPECT_EQ(d.sample().axes[0], 1.0);
    d.setPaused(true);
    d.poll(15.0);
    EXPECT_EQ(d.sample().axes[0], 1.0);
    EXPECT_DOUBLE_EQ(d.position(), 1.0);
    d.setPaused(false);
    d.setSpeed(2.0);
    d.poll(15.5);
    EXPECT_EQ(d.sample().axes[0], -1.0);
    EXPECT_TRUE(d.finished());
    d.start(20.0, 1.5);  // seek back
    d.poll(20.0);
    EXPECT_EQ(d.sample().axes[0], 1.0);
}

TEST(StationEngine, TheKeyboardDrivesInOrderUnlessTheProfileMapsIt)
{
    StationEngine e;
    e.setDrives(5, drives());
    auto keys = std::make_shared<KeyboardDevice>(QStringList{"Q / A", "W / S", "E / D"});
    e.addDevice(keys);
    e.setProfile(twoBanks());  // no keyboard in it
    e.update(0.001);
    keys->setKeys(1, false, true);
    e.update(0.002);
    EXPECT_EQ(e.commands()[2], -1.0);  // second pair → second drive (C 3, tree joint 2)
    EXPECT_EQ(e.state().mappings.size(), 4);  // the profile's own only
    // no gamepad here: the banner and the HUD say that the keyboard drives instead
    // (issue 25, item 5: never "valves closed" while the keys drive them)
    const StationState st = e.state();
    // (three key pairs: the fourth drive, C 5, has no key and holds)
    EXPECT_TRUE(st.setupWarnings.join("").contains(
        "No Gamepad found — valves closed, holding C 5 ROT; the keyboard drives C 1 GIRO, C 3 EXT instead"))
        << st.setupWarnings.join("\n").toStdString();
    EXPECT_FALSE(st.setupWarnings.join("").contains("No Keyboard"));
    // (no catalogue loaded in this test: the plural is the source's "drive(s)")
    EXPECT_TRUE(st.devicesMissing.startsWith("Gamepad missing — the keyboard drives 2 of its 3 drive"))
        << st.devicesMissing.toStdString();
    EXPECT_TRUE(st.devicesMissing.endsWith(", the rest hold")) << st.devicesMissing.toStdString();
    EXPECT_FALSE(st.bankSwitchConnected);  // nothing can switch banks: the HUD shows none
    EXPECT_TRUE(st.bankSwitchHint.isEmpty());
    EXPECT_TRUE(st.warnings.isEmpty());
    StationProfile p = twoBanks();
    p.always.append({"keyboard", 0, 5, 1.0, -1});
    e.setProfile(p);
    e.update(0.003);
    keys->setKeys(0, true, false);
    e.update(0.004);
    EXPECT_EQ(e.commands()[2], 0.0);   // pair 2 no longer mapped
    EXPECT_EQ(e.commands()[4], -1.0);  // pair 1 as the profile says
    // the profile's own keys count too: C 5 follows them, the rest of the pad's hold
    EXPECT_TRUE(e.state().setupWarnings.join("").contains(
        "No Gamepad found — valves closed, holding C 1 GIRO, C 3 EXT; the keyboard drives C 5 ROT instead"))
        << e.state().setupWarnings.join("\n").toStdString();
}

TEST(StationEngine, BanksAreWorthShowingOnlyWithTheDeviceThatSwitchesThem)
{
    Rig r;
    r.engine.setProfile(twoBanks());
    r.step();
    StationState st = r.engine.state();
    EXPECT_TRUE(st.bankSwitchConnected);
    // a gamepad's buttons by their names: next bank 5 = "Guide", A = 0, B = 1
    EXPECT_EQ(st.bankSwitchHint, "Guide: next bank · A: A · B: B");
    EXPECT_TRUE(st.devicesMissing.isEmpty());
    r.pad->setStatus(DeviceStatus::Disconnected);
    r.step();
    st = r.engine.state();
    EXPECT_FALSE(st.bankSwitchConnected);
    EXPECT_TRUE(st.bankSwitchHint.isEmpty());
    EXPECT_TRUE(st.devicesMissing.isEmpty());  // lost, not missing: the warnings say it
    EXPECT_TRUE(st.warnings.join("").contains("Fake sdl:pad1: unplugged — valves closed, holding C 5 ROT, C 1 GIRO, C 3 EXT"))
        << st.warnings.join("\n").toStdString();
}

TEST(StationEngine, DevicesTheProfileListsAreOpenedAndClosedWithIt)
{
    StationEngine e;
    e.setDrives(5, drives());
    StationProfile p = twoBanks();
    p.devices.append({"serial:/dev/padrob-no-such-port", 57600});
    p.devices.append({"comedi:/dev/padrob-no-such-card", 0});
    p.always.append({"serial", 0, 1, 1.0, 1});
    const QList<ProfileIssue> issues = e.setProfile(p);
#ifdef PADROB_HAVE_COMEDI
    EXPECT_TRUE(issues.isEmpty()) << issues.value(0).text().toStdString();
    ASSERT_EQ(e.devices().size(), 2u);
    EXPECT_EQ(e.devices()[1]->info().id, "comedi:/dev/padrob-no-such-card");
#else
    ASSERT_EQ(issues.size(), 1);  // this build has no Comedi: the card is ignored, said why
    EXPECT_TRUE(issues[0].message.contains("Comedi"));
    ASSERT_EQ(e.devices().size(), 1u);
#endif
    EXPECT_EQ(e.devices()[0]->info().id, "serial:/dev/padrob-no-such-port");
    e.update(0.001);
    e.update(0.002);
    EXPECT_EQ(e.devices()[0]->status(), DeviceStatus::Failed);
    EXPECT_TRUE(e.devices()[0]->statusText().contains("/dev/padrob-no-such-port"));
    const StationState st = e.state();
    EXPECT_TRUE(st.warnings.isEmpty());  // never connected: a set-up matter, not the operator's
    EXPECT_TRUE(st.setupWarnings.join("\n").contains("valves closed, holding C 1")) << st.setupWarnings.join("\n").toStdString();
    // no keyboard either: the machine holds, and the operator's line says so
    EXPECT_TRUE(st.devicesMissing.endsWith("missing — its valves are closed, the machine holds"))
        << st.devicesMissing.toStdString();
    // a profile without them closes them
    e.setProfile(twoBanks());
    EXPECT_TRUE(e.devices().empty());
}

TEST(StationEngine, HoldingClosesEveryValveAndLeversAreCentredAfterwards)
{
    Rig r;
    r.engine.setProfile(twoBanks());
    r.step();
    r.pad->setAxis(0, 70);
    EXPECT_NEAR(r.step()[0], 0.7, 1e-12);
    r.engine.setHolding(true);
    EXPECT_EQ(r.step()[0], 0.0);
    EXPECT_TRUE(r.engine.state().warnings.join("").contains("Calibrating"));
    r.engine.setHolding(false);
    EXPECT_EQ(r.step()[0], 0.0);  // still over: waits for the centre
    r.pad->setAxis(0, 0);
    r.step();
    r.pad->setAxis(0, 70);
    EXPECT_NEAR(r.step()[0], 0.7, 1e-12);
}
