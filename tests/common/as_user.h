#pragma once
// Tests that run their own binary again in another setting: as the user "nobody" (a suite
// run as root that checks file permissions), or on a small tmpfs (a full disk).

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QList>
#include <QPair>
#include <QProcess>
#include <QStandardPaths>
#include <QStringList>
#include <QTemporaryDir>

#include <pwd.h>
#include <unistd.h>

namespace padrob_test {

/// What a run of this test binary as another user gave.
struct UserRun {
    bool ran = false;  ///< it started and finished (else `output` says why not)
    int exitCode = -1;
    QString output;    ///< stdout and stderr
};

/// Runs this test binary again as the unprivileged user "nobody" with `args` (a
/// --gtest_filter, a Qt test function) and `env` added: how a suite run as root checks
/// what an ordinary user meets (a read-only file or folder it cannot write; root writes
/// anyway, and dropping capabilities is not enough: access(2) still answers for root).
/// The binary is copied to a folder of its own that "nobody" can read (the build tree
/// may not be), so it must not need files beside it.
inline UserRun runAsUser(const QStringList& args, const QList<QPair<QString, QString>>& env = {})
{
    UserRun r;
    const QString runuser = QStandardPaths::findExecutable("runuser");
    if (runuser.isEmpty() || !getpwnam("nobody")) {
        r.output = "running as root, and there is no runuser(1) or user 'nobody' to run the test as";
        return r;
    }
    QTemporaryDir dir(QDir::tempPath() + "/padrob-as-user-XXXXXX");
    const QString copy = dir.filePath(QFileInfo(QCoreApplication::applicationFilePath()).fileName());
    const auto rx = QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner | QFileDevice::ReadGroup |
                    QFileDevice::ExeGroup | QFileDevice::ReadOther | QFileDevice::ExeOther;
    if (!dir.isValid() || !QFile::setPermissions(dir.path(), rx) ||
        !QFile::copy(QCoreApplication::applicationFilePath(), copy) || !QFile::setPermissions(copy, rx)) {
        r.output = "cannot copy the test binary to a folder of its own";
        return r;
    }
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    QStringList command{"-u", "nobody", "--", "env", "HOME=" + dir.path()};
    for (const auto& [name, value] : env) command << name + "=" + value;
    command << copy << args;
    p.start(runuser, command);
    r.ran = p.waitForFinished(120000) && p.exitStatus() == QProcess::NormalExit;
    r.exitCode = p.exitCode();
    r.output = QString::fromLocal8Bit(p.readAll());
    return r;
}

/// What a run of this test binary on a small, private tmpfs gave.
struct TmpfsRun {
    bool mounted = false;  ///< false: no tmpfs could be mounted here (`output` says why)
    bool passed = false;   ///< the child exited 0 having passed its one test
    QString output;        ///< stdout and stderr
};

/// Runs this test binary with `filter` in a private mount namespace (unshare -m, as root)
/// where `folder` is a tmpfs of `size` (e.g. "64k"); `env` names an environment variable
/// set to `folder` for the child.
inline TmpfsRun runOnSmallTmpfs(const QString& folder, const QString& size, const QString& env, const QString& filter)
{
    TmpfsRun r;
    const QString unshare = QStandardPaths::findExecutable("unshare");
    if (geteuid() != 0 || unshare.isEmpty()) {
        r.output = "needs root and unshare(1) to mount a small tmpfs in a private mount namespace";
        return r;
    }
    QProcess child;
    QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
    e.insert(env, folder);
    child.setProcessEnvironment(e);
    child.start(unshare, {"-m", "--propagation", "private", "sh", "-c",
                          "mount -t tmpfs -o size=" + size + " padrob-full \"$0\" || exit 77; exec \"$1\" \"$2\"", folder,
                          QCoreApplication::applicationFilePath(), "--gtest_filter=" + filter});
    const bool finished = child.waitForFinished(60000);
    const QString err = QString::fromLocal8Bit(child.readAllStandardError());
    const QString out = QString::fromLocal8Bit(child.readAllStandardOutput());
    if (child.exitCode() == 77 || err.startsWith("unshare:")) {
        r.output = "cannot mount a small tmpfs here: " + err.trimmed();
        return r;
    }
    r.mounted = true;
    r.output = out + err;
    r.passed = finished && child.exitStatus() == QProcess::NormalExit && child.exitCode() == 0 &&
               out.contains("[  PASSED  ] 1 test");
    return r;
}

}  // namespace padrob_test
