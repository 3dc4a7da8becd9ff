#pragma once
// The serial DAQ box's end of a pseudo-terminal pair, for tests: the device under
// test opens the slave's path, the test plays the box on the master side.
#include <QElapsedTimer>
#include <QString>

#include <cerrno>
#include <fcntl.h>
#include <functional>
#include <pty.h>
#include <string>
#include <string_view>
#include <termios.h>
#include <unistd.h>

namespace test {

// the box's end of a pseudo-terminal pair: raw, non-blocking
class PtyMaster {
public:
    PtyMaster()
    {
        if (::openpty(&m_fd, &m_slave, nullptr, nullptr, nullptr) != 0) {
            m_fd = m_slave = -1;
            return;
        }
        termios t{};
        ::tcgetattr(m_fd, &t);
        ::cfmakeraw(&t);
        ::tcsetattr(m_fd, TCSANOW, &t);
        ::fcntl(m_fd, F_SETFL, ::fcntl(m_fd, F_GETFL) | O_NONBLOCK);
        m_slavePath = QString::fromLocal8Bit(::ptsname(m_fd));
    }
    ~PtyMaster()
    {
        close();
        if (m_slave >= 0)
            ::close(m_slave);
    }
    PtyMaster(const PtyMaster&) = delete;
    PtyMaster& operator=(const PtyMaster&) = delete;

    bool ok() const { return m_fd >= 0; }
    QString slavePath() const { return m_slavePath; }
    // the port vanishes for the device (as a USB unplug). Our slave descriptor stays
    // open, so that the pty's number is not given to another process (ctest -j) whose
    // pty the device's retries would then open.
    void close()
    {
        if (m_fd >= 0)
            ::close(m_fd);
        m_fd = -1;
    }

    // writes all of `bytes`, running `pump` while the pty is full; false after 500 ms
    bool write(std::string_view bytes, const std::function<void()>& pump)
    {
        QElapsedTimer timer;
        timer.start();
        while (!bytes.empty()) {
            const ssize_t n = ::write(m_fd, bytes.data(), bytes.size());
            if (n > 0) {
                bytes.remove_prefix(std::size_t(n));
                continue;
            }
            if (n < 0 && errno != EAGAIN && errno != EINTR)
                return false;
            if (timer.elapsed() > 500)
                return false;
            pump();
            ::usleep(200);
        }
        return true;
    }

    // everything the host has sent so far
    const std::string& received()
    {
        char buf[256];
        ssize_t n = 0;
        while (m_fd >= 0 && (n = ::read(m_fd, buf, sizeof buf)) > 0)
            m_received.append(buf, std::size_t(n));
        return m_received;
    }

private:
    int m_fd = -1;     // master
    int m_slave = -1;  // held, never read: the device opens the slave by name
    QString m_slavePath;
    std::string m_received;
};

}  // namespace test
