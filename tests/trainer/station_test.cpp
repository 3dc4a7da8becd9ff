// The Station: the engine in its own input thread, talked to by post()/call() and
// latest(); commands reach the sink from that thread.
#include "trainer/input/keyboard_device.h"
#include "trainer/station/station.h"

#include <QThread>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

using namespace trainer;

namespace {

template <class F>
bool waitFor(F done, int ms = 2000)
{
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
    while (std::chrono::steady_clock::now() < end) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    return done();
}

}  // namespace

TEST(Station, RunsTheEngineInItsOwnThreadAndFeedsTheSink)
{
    std::mutex m;
    std::vector<double> last;
    std::atomic<int> calls{0};
    std::atomic<Qt::HANDLE> sinkThread{nullptr};
    Station station([&](std::span<const double> u) {
        std::lock_guard lock(m);
        last.assign(u.begin(), u.end());
        sinkThread = QThread::currentThreadId();
        ++calls;
    });
    station.start(false);
    EXPECT_TRUE(station.isRunning());
    auto keys = std::make_shared<KeyboardDevice>(QStringList{"Q / A", "W / S"});
    std::atomic<Qt::HANDLE> engineThread{nullptr};
    station.call([&](StationEngine& e) {
        engineThread = QThread::currentThreadId();
        e.setDrives(3, {{0, 1, "A"}, {2, 3, "B"}});
        e.addDevice(keys);
        StationProfile p;
        p.name = "keys";
        p.banks.append({"-", {}, {}});
        e.setProfile(p);
    });
    EXPECT_NE(engineThread.load(), QThread::currentThreadId());
    // an update with the profile and the keys released (a key held while a profile is
    // installed must be released before it acts)
    ASSERT_TRUE(waitFor([&] { return station.latest() && station.latest()->profileName == "keys"; }));
    keys->setKeys(1, false, true);
    ASSERT_TRUE(waitFor([&] {
        std::lock_guard lock(m);
        return last.size() == 3 && last[2] == -1.0;
    }));
    EXPECT_EQ(sinkThread.load(), engineThread.load());
    ASSERT_TRUE(waitFor([&] {
        auto st = station.latest();
        return st && st->profileName == "keys" && st->commands.size() == 3 && st->commands[2] == -1.0;
    }));
    station.stop();
    EXPECT_FALSE(station.isRunning());
    const int after = calls;
    keys->setKeys(1, false, false);
    station.post([](StationEngine&) { FAIL() << "ran after stop"; });
    station.call([](StationEngine&) { FAIL() << "ran after stop"; });
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_EQ(calls.load(), after);
}

TEST(Station, WithoutStartPostRunsAtOnce)
{
    Station station;
    bool ran = false;
    station.post([&](StationEngine& e) { ran = e.devices().empty(); });
    EXPECT_TRUE(ran);
}
