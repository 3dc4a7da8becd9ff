// SerialDaq over a pseudo-terminal pair: the device opens the slave's path, the test
// plays the console box on the master side.
#include "pty_master.h"

#include "trainer/input/serial_daq.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <fcntl.h>
#include <functional>
#include <pty.h>
#include <string>
#include <string_view>
#include <termios.h>
#include <unistd.h>
#include <vector>

using trainer::DeviceStatus;
using trainer::SerialDaq;
namespace daq = trainer::daq;
using test::PtyMaster;

namespace {

std::size_t countOf(const std::string& s, std::string_view what)
{
    std::size_t n = 0;
    for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + what.size()))
        ++n;
    return n;
}

std::string ident(int channels = 8, int rate = 100, std::string name = "Bench console", int bits = 10)
{
    return daq::identificationLine({daq::kProtocolVersion, channels, bits, rate, std::move(name)});
}

std::vector<std::uint16_t> values(int channels, int base)
{
    std::vector<std::uint16_t> v;
    for (int i = 0; i < channels; ++i)
        v.push_back(std::uint16_t((base + 37 * i) % 1024));
    return v;
}

std::string line(std::uint16_t seq, int channels = 8)
{
    return daq::sampleLine(seq, values(channels, seq));
}

void expectValues(const trainer::DeviceSample& s, int channels, int base)
{
    ASSERT_EQ(s.axes.size(), std::size_t(channels));
    const auto v = values(channels, base);
    for (int i = 0; i < channels; ++i)
        EXPECT_EQ(s.axes[std::size_t(i)], double(v[std::size_t(i)])) << "axis " << i;
}

class SerialDaqPty : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(pty.ok()) << "openpty failed"; }

    // polls (and runs the event loop, unless told not to) until `done` or 500 ms
    bool pollUntil(SerialDaq& d, const std::function<bool()>& done, bool events = true)
    {
        QElapsedTimer timer;
        timer.start();
        for (;;) {
            if (events)
                QCoreApplication::processEvents();
            d.poll(now);
            if (done())
                return true;
            if (timer.elapsed() > 500)
                return false;
            ::usleep(200);
        }
    }
    bool send(SerialDaq& d, std::string_view bytes, bool events = true)
    {
        return pty.write(bytes, [&] {
            if (events)
                QCoreApplication::processEvents();
            d.poll(now);
        });
    }

    PtyMaster pty;
    double now = 0.0;  // the station clock [s]
};

}  // namespace

TEST(SerialDaq, StaticHelpers)
{
    const QList<qint32> rates = SerialDaq::standardBaudRates();
    EXPECT_TRUE(rates.contains(9600));
    EXPECT_TRUE(rates.contains(SerialDaq::kDefaultBaudRate));
    EXPECT_TRUE(rates.contains(921600));
    EXPECT_TRUE(std::is_sorted(rates.begin(), rates.end()));
    for (const SerialDaq::PortEntry& p : SerialDaq::availablePorts())  // whatever this machine has
        EXPECT_FALSE(p.name.isEmpty());
}

TEST(SerialDaq, MissingPortFailsAndIsRetriedEverySecond)
{
    const QString port = "/nonexistent/ttyPADROB";
    SerialDaq d(port);
    EXPECT_EQ(d.info().id, "serial:" + port);
    EXPECT_EQ(d.info().kind, trainer::DeviceKind::SerialDaq);
    EXPECT_TRUE(d.info().name.contains(port));
    EXPECT_EQ(d.status(), DeviceStatus::Failed);
    EXPECT_TRUE(d.statusText().contains(port)) << d.statusText().toStdString();
    EXPECT_FALSE(d.isOpen());
    EXPECT_EQ(d.openAttempts(), 1u);
    const std::vector<std::pair<double, std::uint64_t>> polls = {
        {10.0, 1}, {10.5, 1}, {11.0, 2}, {11.9, 2}, {12.0, 3}, {15.0, 4}};
    for (const auto& [t, attempts] : polls) {
        d.poll(t);
        EXPECT_EQ(d.openAttempts(), attempts) << "at " << t;
        EXPECT_EQ(d.status(), DeviceStatus::Failed);
        EXPECT_FALSE(d.statusText().isEmpty());
    }
    EXPECT_EQ(d.sample().count, 0u);
    EXPECT_EQ(d.sample().time, -1.0);
}

TEST_F(SerialDaqPty, IdentificationAndSamplesArrive)
{
    SerialDaq d(pty.slavePath());
    EXPECT_TRUE(d.isOpen());
    EXPECT_EQ(d.status(), DeviceStatus::Connected);
    EXPECT_EQ(d.info().id, "serial:" + pty.slavePath());
    EXPECT_EQ(d.info().name, "DAQ console on " + pty.slavePath());
    EXPECT_TRUE(d.info().axes.isEmpty());
    EXPECT_EQ(d.infoVersion(), 0u);

    // the host asks the box who it is
    ASSERT_TRUE(pollUntil(d, [&] { return pty.received().find("?\n") != std::string::npos; }));

    now = 3.0;
    ASSERT_TRUE(send(d, ident(8, 100, "Bench console") + line(0) + line(1) + line(2)));
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 3; }));
    EXPECT_EQ(d.status(), DeviceStatus::Connected);
    EXPECT_EQ(d.statusText(), "");
    EXPECT_EQ(d.infoVersion(), 1u);
    const trainer::DeviceInfo& info = d.info();
    EXPECT_EQ(info.name, "Bench console");
    ASSERT_EQ(info.axes.size(), 8);
    EXPECT_EQ(info.axes[0].name, "Lever 1");
    EXPECT_EQ(info.axes[7].name, "Lever 8");
    EXPECT_EQ(info.axes[3].rawMin, 0.0);
    EXPECT_EQ(info.axes[3].rawRest, 511.5);
    EXPECT_EQ(info.axes[3].rawMax, 1023.0);
    EXPECT_TRUE(info.buttons.isEmpty());
    expectValues(d.sample(), 8, 2);
    EXPECT_EQ(d.sample().time, 3.0);
    ASSERT_TRUE(d.identification());
    EXPECT_EQ(d.identification()->rate, 100);
    EXPECT_EQ(d.stats().goodLines, 3u);
    EXPECT_EQ(d.stats().identLines, 1u);
    EXPECT_EQ(d.droppedSamples(), 0u);
    EXPECT_DOUBLE_EQ(d.stallTimeout(), 0.25);  // 20 periods at 100 Hz is less

    // a slower box waits longer before it counts as stalled, but never over 0.3 s,
    // whatever rate it claims (a box that says 1 Hz and freezes keeps no valve open)
    ASSERT_TRUE(send(d, ident(8, 70, "Bench console")));
    ASSERT_TRUE(pollUntil(d, [&] { return d.stats().identLines == 2; }));
    EXPECT_NEAR(d.stallTimeout(), 20.0 / 70.0, 1e-12);
    ASSERT_TRUE(send(d, ident(8, 1, "Bench console")));
    ASSERT_TRUE(pollUntil(d, [&] { return d.stats().identLines == 3; }));
    EXPECT_DOUBLE_EQ(d.stallTimeout(), SerialDaq::kMaxStallTimeout);
    EXPECT_DOUBLE_EQ(SerialDaq::kMaxStallTimeout, 0.3);
    EXPECT_EQ(d.infoVersion(), 1u);  // same name and axes
}

TEST_F(SerialDaqPty, WorksWhenTheOwnerOnlyPolls)
{
    // no event loop at all: poll() reads with waitForReadyRead(0) and writes with
    // waitForBytesWritten(0)
    SerialDaq d(pty.slavePath());
    ASSERT_TRUE(pollUntil(d, [&] { return pty.received().find("?\n") != std::string::npos; }, false));
    ASSERT_TRUE(send(d, ident(4) + line(0, 4) + line(1, 4), false));
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 2; }, false));
    expectValues(d.sample(), 4, 1);
    EXPECT_EQ(d.status(), DeviceStatus::Connected);
}

TEST_F(SerialDaqPty, ChannelCountFromTheFirstLineUntilAnIdentification)
{
    SerialDaq d(pty.slavePath());
    ASSERT_TRUE(send(d, line(0, 3) + line(1, 3)));
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 2; }));
    EXPECT_EQ(d.infoVersion(), 1u);
    ASSERT_EQ(d.info().axes.size(), 3);
    EXPECT_EQ(d.info().axes[2].rawMax, 1023.0);  // 10 bits until told
    EXPECT_TRUE(d.info().name.contains(pty.slavePath()));
    expectValues(d.sample(), 3, 1);

    // lines of another width are dropped
    ASSERT_TRUE(send(d, line(2, 5) + line(3, 3)));
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 3; }));
    EXPECT_EQ(d.stats().wrongChannels, 1u);

    // the identification decides: 12 bits, a name
    ASSERT_TRUE(send(d, ident(3, 50, "Twelve", 12) + line(0, 3)));
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 4; }));
    EXPECT_EQ(d.infoVersion(), 2u);
    EXPECT_EQ(d.info().name, "Twelve");
    EXPECT_EQ(d.info().axes[2].rawMax, 4095.0);
    EXPECT_EQ(d.info().axes[2].rawRest, 2047.5);
}

TEST_F(SerialDaqPty, CorruptLinesAreDroppedAndCounted)
{
    SerialDaq d(pty.slavePath());
    std::string badCrc = line(1);
    badCrc[badCrc.size() - 2] = badCrc[badCrc.size() - 2] == '0' ? '1' : '0';
    std::string flipped = line(2);
    flipped[3] = flipped[3] == '5' ? '6' : '5';  // a digit of the first value
    const std::string truncated = line(3).substr(0, 15) + "\n";
    ASSERT_TRUE(send(d, ident() + line(0) + badCrc + flipped + truncated + "noise\n" + line(4)));
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 2; }));
    expectValues(d.sample(), 8, 4);
    const daq::Stats& st = d.stats();
    EXPECT_EQ(st.goodLines, 2u);
    EXPECT_EQ(st.badChecksum, 2u);
    EXPECT_EQ(st.badSyntax, 1u);
    EXPECT_EQ(st.garbageLines, 1u);
    EXPECT_EQ(st.lostSamples, 3u);
    EXPECT_EQ(d.droppedSamples(), 3u);
    EXPECT_EQ(d.status(), DeviceStatus::Connected);
}

TEST_F(SerialDaqPty, BurstOf1000LinesIsReadWhole)
{
    SerialDaq d(pty.slavePath());
    std::string burst = ident();
    for (int k = 0; k < 1000; ++k)
        burst += line(std::uint16_t(k));
    ASSERT_TRUE(send(d, burst));  // as fast as the pty takes it
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 1000; }));
    EXPECT_EQ(d.stats().goodLines, 1000u);
    EXPECT_EQ(d.stats().lostSamples, 0u);
    EXPECT_EQ(d.droppedSamples(), 0u);
    expectValues(d.sample(), 8, 999);
}

TEST_F(SerialDaqPty, StallAndRecovery)
{
    SerialDaq d(pty.slavePath());
    ASSERT_TRUE(send(d, ident(8, 100) + line(0)));
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 1; }));
    EXPECT_EQ(d.status(), DeviceStatus::Connected);

    // the box goes quiet: 0.25 s of station time is allowed
    now = 0.2;
    d.poll(now);
    EXPECT_EQ(d.status(), DeviceStatus::Connected);
    now = 0.3;
    d.poll(now);
    EXPECT_EQ(d.status(), DeviceStatus::Stalled);
    EXPECT_TRUE(d.statusText().contains("0.3")) << d.statusText().toStdString();
    now = 5.0;
    d.poll(now);
    EXPECT_EQ(d.status(), DeviceStatus::Stalled);
    EXPECT_TRUE(d.statusText().contains("5.0")) << d.statusText().toStdString();
    EXPECT_TRUE(d.isOpen());

    // the next good line brings it back
    ASSERT_TRUE(send(d, line(1)));
    ASSERT_TRUE(pollUntil(d, [&] { return d.status() == DeviceStatus::Connected; }));
    EXPECT_EQ(d.statusText(), "");
    EXPECT_EQ(d.sample().count, 2u);
    EXPECT_EQ(d.sample().time, 5.0);

    // a longer timeout when set
    d.setStallTimeout(2.0);
    now = 6.5;
    d.poll(now);
    EXPECT_EQ(d.status(), DeviceStatus::Connected);
    now = 7.1;
    d.poll(now);
    EXPECT_EQ(d.status(), DeviceStatus::Stalled);
}

TEST_F(SerialDaqPty, ABoxThatClaimsOneHertzAndFreezesStallsWithinThreeTenthsOfASecond)
{
    SerialDaq d(pty.slavePath());
    ASSERT_TRUE(send(d, ident(8, 1) + line(900)));  // a lever held
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 1; }));
    EXPECT_EQ(d.status(), DeviceStatus::Connected);
    now = 0.29;
    d.poll(now);
    EXPECT_EQ(d.status(), DeviceStatus::Connected);
    now = 0.31;
    d.poll(now);
    EXPECT_EQ(d.status(), DeviceStatus::Stalled);
}

TEST_F(SerialDaqPty, AsksAgainUntilIdentified)
{
    SerialDaq d(pty.slavePath());
    ASSERT_TRUE(pollUntil(d, [&] { return countOf(pty.received(), "?\n") == 1; }));
    // once a second of station time, three more times
    for (now = 0.25; now < 10.0; now += 0.25) {
        QCoreApplication::processEvents();
        d.poll(now);
    }
    ASSERT_TRUE(pollUntil(d, [&] { return countOf(pty.received(), "?\n") == 4; }));
    EXPECT_EQ(countOf(pty.received(), "?\n"), 4u);
    EXPECT_EQ(d.status(), DeviceStatus::Stalled);  // nothing came

    // asked by hand
    d.requestIdentification();
    ASSERT_TRUE(pollUntil(d, [&] { return countOf(pty.received(), "?\n") == 5; }));
}

TEST_F(SerialDaqPty, SampleRateIsAskedUntilTheBoxReportsIt)
{
    SerialDaq d(pty.slavePath());
    EXPECT_FALSE(d.setSampleRate(0));
    EXPECT_FALSE(d.setSampleRate(1001));
    EXPECT_TRUE(d.setSampleRate(250));
    ASSERT_TRUE(pollUntil(d, [&] { return countOf(pty.received(), "R250\n") == 1; }));
    // the box answers with its old rate (it missed the command): asked again
    ASSERT_TRUE(send(d, ident(8, 100)));
    ASSERT_TRUE(pollUntil(d, [&] { return countOf(pty.received(), "R250\n") == 2; }));
    // now it reports 250 Hz: no more asking
    ASSERT_TRUE(send(d, ident(8, 250) + line(0)));
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 1; }));
    EXPECT_EQ(d.identification()->rate, 250);
    ASSERT_TRUE(send(d, ident(8, 250)));
    ASSERT_TRUE(pollUntil(d, [&] { return d.stats().identLines == 3; }));
    EXPECT_EQ(countOf(pty.received(), "R250\n"), 2u);
}

TEST_F(SerialDaqPty, VanishedPortIsDisconnectedAndRetried)
{
    SerialDaq d(pty.slavePath());
    ASSERT_TRUE(send(d, ident() + line(0)));
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 1; }));

    pty.close();  // unplugged
    now = 1.0;
    ASSERT_TRUE(pollUntil(d, [&] { return d.status() != DeviceStatus::Connected; }));
    EXPECT_EQ(d.status(), DeviceStatus::Disconnected);
    EXPECT_FALSE(d.isOpen());
    EXPECT_TRUE(d.statusText().contains(pty.slavePath())) << d.statusText().toStdString();
    // the last good sample stays
    EXPECT_EQ(d.sample().count, 1u);
    expectValues(d.sample(), 8, 0);

    // retried every second, never connected, never crashing
    const std::uint64_t attempts = d.openAttempts();
    for (int i = 1; i <= 10; ++i) {
        now = 1.0 + 0.5 * i;
        QCoreApplication::processEvents();
        d.poll(now);
        EXPECT_NE(d.status(), DeviceStatus::Connected);
        EXPECT_FALSE(d.statusText().isEmpty());
    }
    EXPECT_GE(d.openAttempts(), attempts + 4);
    EXPECT_LE(d.openAttempts(), attempts + 5);
}

TEST_F(SerialDaqPty, ComesBackAfterReplug)
{
    // a stable name for the port (as /dev/serial/by-id/… is), pointing to a new pty
    // after the "re-plug"
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString link = dir.filePath("ttyPadrobDaq");
    ASSERT_TRUE(QFile::link(pty.slavePath(), link));
    SerialDaq d(link);
    EXPECT_EQ(d.info().id, "serial:" + link);
    ASSERT_TRUE(send(d, ident() + line(0)));
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 1; }));

    pty.close();
    now = 1.0;
    ASSERT_TRUE(pollUntil(d, [&] { return d.status() == DeviceStatus::Disconnected; }));
    d.poll(2.0);  // a retry while the port is still gone
    EXPECT_EQ(d.status(), DeviceStatus::Disconnected);
    EXPECT_FALSE(d.isOpen());

    PtyMaster pty2;
    ASSERT_TRUE(pty2.ok());
    ASSERT_TRUE(QFile::remove(link));
    ASSERT_TRUE(QFile::link(pty2.slavePath(), link));
    now = 3.0;
    d.poll(now);
    EXPECT_TRUE(d.isOpen());
    EXPECT_EQ(d.status(), DeviceStatus::Connected);
    ASSERT_TRUE(pollUntil(d, [&] { return pty2.received().find("?\n") != std::string::npos; }));
    ASSERT_TRUE(pty2.write(ident() + line(1), [&] { d.poll(now); }));
    ASSERT_TRUE(pollUntil(d, [&] { return d.sample().count == 2; }));
    expectValues(d.sample(), 8, 1);
    EXPECT_EQ(d.info().id, "serial:" + link);
    EXPECT_EQ(d.infoVersion(), 1u);  // the same box again
}
