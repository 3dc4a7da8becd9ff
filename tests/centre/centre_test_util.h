#pragma once
// Shared by the centre's tests: a DDS domain per test process, and waiting for things.

#include "trainer/centre/messages.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QThread>

#include <functional>
#include <string>
#include <unistd.h>

namespace centre_test {

/// A DDS domain for this test process: tests run in parallel, each in its own domain
/// (names carry the pid too, so a chance collision cannot mix them up).
inline int domain() { return 1 + static_cast<int>(::getpid() % 230); }
inline std::string unique(const std::string& name) { return name + "-" + std::to_string(::getpid()); }

/// A reply that says a command was done (a station's, or a forger's).
inline trainer::centre::Reply doneReply(const std::string& station, const std::string& sender, std::uint64_t nonce)
{
    trainer::centre::Reply r;
    r.station = station;
    r.sender = sender;
    r.nonce = nonce;
    r.accepted = true;
    r.message = "done";
    return r;
}

/// Polls `done` (calling `poll` first) every 10 ms for up to `ms`.
inline bool waitFor(const std::function<bool()>& done, int ms, const std::function<void()>& poll = {})
{
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms) {
        if (poll) poll();
        if (done()) return true;
        QCoreApplication::processEvents();
        QThread::msleep(10);
    }
    if (poll) poll();
    return done();
}

}  // namespace centre_test
