// The station with the serial DAQ console over a pseudo-terminal pair: the profile
// lists the port, the station opens it, the levers drive the valves through the
// console profile; corrupt lines are dropped, a stall closes the valves with a
// warning, and the levers take over again once centred.
#include "pty_master.h"

#include "trainer/input/daq_protocol.h"
#include "trainer/station/station_engine.h"

#include <QCoreApplication>

#include <gtest/gtest.h>

using namespace trainer;
namespace daq = trainer::daq;

namespace {

QList<DriveInfo> eightDrives()
{
    QList<DriveInfo> d;
    for (int i = 0; i < 9; ++i) d.append({i, i + 1, QString("C%1").arg(i + 1)});
    return d;
}

/// The shipped console's mapping: levers 1–7 on C 1–7, lever 8 on both claws.
StationProfile console(const QString& port)
{
    StationProfile p;
    p.name = "console";
    p.devices.append({"serial:" + port, 115200});
    for (int i = 0; i < 7; ++i) p.always.append({"serial", i, i + 1, 1.0, 1});
    p.always.append({"serial", 7, 8, 1.0, -1});
    p.always.append({"serial", 7, 9, 1.0, 1});
    p.banks.append({"Console", {}, {}});
    ChannelCalibration c{0, 512, 1023, 0.02, 0.02};
    c.captured = true;
    for (int i = 0; i < 8; ++i) p.setCalibration("serial", i, c);
    return p;
}

std::string sample(std::uint16_t seq, std::vector<std::uint16_t> v)
{
    return daq::sampleLine(seq, v);
}

struct Rig {
    test::PtyMaster pty;
    StationEngine engine;
    double now = 0.0;

    void update()
    {
        QCoreApplication::processEvents();
        engine.update(now += 1e-3);
    }
    bool send(const std::string& bytes)
    {
        return pty.write(bytes, [&] { update(); });
    }
    /// Updates until `done` (at most 500 station steps of 1 ms, each with a short real wait).
    template <class F>
    bool until(F done)
    {
        for (int i = 0; i < 500; ++i) {
            update();
            if (done()) return true;
            ::usleep(300);
        }
        return false;
    }
    const DeviceState* device()
    {
        static StationState st;
        st = engine.state();
        return st.devices.isEmpty() ? nullptr : &st.devices[0];
    }
};

}  // namespace

TEST(StationSerial, TheConsoleDrivesTheValvesDropsBadLinesAndHoldsOnAStall)
{
    Rig r;
    ASSERT_TRUE(r.pty.ok());
    r.engine.setDrives(9, eightDrives());
    const QList<ProfileIssue> issues = r.engine.setProfile(console(r.pty.slavePath()));
    ASSERT_TRUE(issues.isEmpty()) << issues.value(0).text().toStdString();
    ASSERT_EQ(r.engine.devices().size(), 1u);
    EXPECT_EQ(r.engine.devices()[0]->info().id, "serial:" + r.pty.slavePath());

    std::vector<std::uint16_t> rest(8, 512);
    std::uint16_t seq = 0;
    ASSERT_TRUE(r.send(daq::identificationLine({daq::kProtocolVersion, 8, 10, 500, "Consola"}) + sample(seq++, rest)));
    ASSERT_TRUE(r.until([&] { return r.device() && r.device()->status == DeviceStatus::Connected &&
                                     r.device()->channels.size() == 8; }));
    EXPECT_EQ(r.device()->info.name, "Consola");

    // lever 2 to full travel, lever 8 half closed: C 2 +1, the claws ∓0.5
    std::vector<std::uint16_t> moved = rest;
    moved[1] = 1023;
    moved[7] = 256;
    // a corrupt line in between (a flipped digit: the checksum no longer matches)
    std::string bad = sample(seq++, {512, 0, 512, 512, 512, 512, 512, 512});
    bad[bad.find(",0,") + 1] = '9';
    ASSERT_TRUE(r.send(bad + sample(seq++, moved)));
    ASSERT_TRUE(r.until([&] { return r.engine.commands()[1] == 1.0; }));
    EXPECT_NEAR(r.engine.commands()[7], (0.5 - 0.02) / 0.98, 1e-12);  // C 8's sign is −1
    EXPECT_NEAR(r.engine.commands()[8], -r.engine.commands()[7], 1e-12);
    EXPECT_EQ(r.engine.commands()[0], 0.0);
    EXPECT_EQ(r.device()->dropped, 1u);
    EXPECT_GE(r.device()->samples, 2u);

    // a burst of 500 lines, the last one wins
    std::string burst;
    for (int i = 0; i < 500; ++i) {
        std::vector<std::uint16_t> v = rest;
        v[0] = std::uint16_t(512 + i);
        burst += sample(seq++, v);
    }
    ASSERT_TRUE(r.send(burst));
    ASSERT_TRUE(r.until([&] { return r.device()->samples >= 502u && r.engine.commands()[0] > 0.9; }));
    EXPECT_NEAR(r.engine.commands()[0], (1011.0 - 512.0) / 511.0 * 1.0 / 0.98 - 0.02 / 0.98, 1e-9);

    // the box stalls (the cable hangs): after the stall timeout the valves close
    ASSERT_TRUE(r.until([&] { return r.device()->status == DeviceStatus::Stalled; }));
    for (double u : r.engine.commands()) EXPECT_EQ(u, 0.0);
    const QString warnings = r.engine.state().warnings.join("\n");
    EXPECT_TRUE(warnings.contains("Consola")) << warnings.toStdString();
    EXPECT_TRUE(warnings.contains("C2")) << warnings.toStdString();

    // it comes back with lever 2 still over: nothing moves until that lever is centred
    ASSERT_TRUE(r.send(sample(seq++, moved)));
    ASSERT_TRUE(r.until([&] { return r.device()->status == DeviceStatus::Connected; }));
    r.update();
    EXPECT_EQ(r.engine.commands()[1], 0.0);
    ASSERT_TRUE(r.send(sample(seq++, rest)));
    ASSERT_TRUE(r.until([&] { return r.engine.state().warnings.isEmpty(); }));  // armed again
    ASSERT_TRUE(r.send(sample(seq++, moved)));
    ASSERT_TRUE(r.until([&] { return r.engine.commands()[1] == 1.0; }));
    EXPECT_TRUE(r.engine.state().warnings.isEmpty());

    // the port vanishes (USB unplugged): valves closed, the station keeps running
    r.pty.close();
    ASSERT_TRUE(r.until([&] { return r.device()->status != DeviceStatus::Connected; }));
    for (int i = 0; i < 50; ++i) r.update();
    for (double u : r.engine.commands()) EXPECT_EQ(u, 0.0);
    EXPECT_FALSE(r.engine.state().warnings.isEmpty());
}
