#pragma once
// A throwaway PostgreSQL server for the records tests (records_test.cpp,
// shared_records_test.cpp), and a plain QPSQL connection of the test's own to look at it.

#include "trainer/records/records_db.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <algorithm>
#include <memory>

#include <pwd.h>
#include <unistd.h>

namespace padrob_test {

/// A throwaway PostgreSQL server: initdb in a temporary folder, listening only on a
/// Unix socket there, trust authentication, stopped (immediately) at the end. As root
/// it runs as "nobody", who owns the folder (postgres refuses to run as root).
class LocalPostgres {
public:
    ~LocalPostgres() { stop(); }

    /// False with `why` when it cannot be started here.
    bool start(QString& why)
    {
        if (!QSqlDatabase::isDriverAvailable("QPSQL")) {
            why = "the Qt PostgreSQL driver (QPSQL; Debian package libqt6sql6-psql) is not installed";
            return false;
        }
        QStringList bins = QDir("/usr/lib/postgresql").entryList(QDir::Dirs | QDir::NoDotAndDotDot);
        std::sort(bins.begin(), bins.end(), [](const QString& a, const QString& b) { return a.toInt() > b.toInt(); });
        for (const QString& v : bins) {
            const QString bin = "/usr/lib/postgresql/" + v + "/bin/";
            if (QFileInfo::exists(bin + "initdb") && QFileInfo::exists(bin + "pg_ctl")) {
                m_bin = bin;
                break;
            }
        }
        if (m_bin.isEmpty() && !QStandardPaths::findExecutable("initdb").isEmpty())
            m_bin = QFileInfo(QStandardPaths::findExecutable("initdb")).absolutePath() + "/";
        if (m_bin.isEmpty()) {
            why = "the PostgreSQL server programs (initdb, pg_ctl) are not installed (/usr/lib/postgresql/*/bin)";
            return false;
        }
        // a short path: a Unix socket's path is limited to ~100 bytes
        m_dir = std::make_unique<QTemporaryDir>("/tmp/padrob-pg-XXXXXX");
        if (!m_dir->isValid()) {
            why = "cannot create a temporary folder in /tmp";
            return false;
        }
        if (geteuid() == 0) {
            const passwd* nobody = getpwnam("nobody");
            const QString runuser = QStandardPaths::findExecutable("runuser");
            if (!nobody || runuser.isEmpty()) {
                why = "running as root, and there is no user 'nobody' or no runuser(1) to run the server as";
                return false;
            }
            if (chown(QFile::encodeName(m_dir->path()).constData(), nobody->pw_uid, nobody->pw_gid) != 0) {
                why = "cannot give the temporary folder to 'nobody'";
                return false;
            }
            m_prefix = {runuser, "-u", "nobody", "--"};
        }
        const QString data = m_dir->filePath("data");
        QString out;
        const QStringList initdb = {"-D", data, "-A", "trust", "-U", "padrob", "-E", "UTF8",
                                    "--no-sync", "--no-locale"};
        if (!run("initdb", initdb, out)) {
            why = "initdb failed: " + out.trimmed();
            return false;
        }
        return resume(why);
    }
    /// Starts the server again on its data after stop() (as after an outage).
    bool resume(QString& why)
    {
        if (m_running) return true;
        const QString options = QStringLiteral("-k %1 -c listen_addresses='' -F").arg(m_dir->path());
        QString out;
        if (!run("pg_ctl", {"-D", m_dir->filePath("data"), "-l", m_dir->filePath("log"), "-o", options, "-w", "-t",
                            "20", "start"},
                 out)) {
            QFile log(m_dir->filePath("log"));
            why = "pg_ctl start failed: " + out.trimmed() + " " +
                  (log.open(QIODevice::ReadOnly) ? QString::fromLocal8Bit(log.readAll()).trimmed() : QString());
            return false;
        }
        m_running = true;
        return true;
    }
    /// Stops the server at once (as a crash or a cut cable would: sessions just end).
    void stop()
    {
        if (!m_running) return;
        QString out;
        run("pg_ctl", {"-D", m_dir->filePath("data"), "-m", "immediate", "-w", "stop"}, out);
        m_running = false;
    }
    bool running() const { return m_running; }
    trainer::records::PostgresConfig config() const
    {
        trainer::records::PostgresConfig c;
        c.host = m_dir->path();  // the socket's folder
        c.database = "postgres";
        c.user = "padrob";
        c.password = "not-Used-with-trust-7";
        return c;
    }

private:
    bool run(const QString& program, const QStringList& args, QString& out)
    {
        QProcess p;
        p.setWorkingDirectory(m_dir->path());
        p.setProcessChannelMode(QProcess::MergedChannels);
        QStringList all = m_prefix;
        all << m_bin + program << args;
        p.start(all.takeFirst(), all);
        const bool finished = p.waitForFinished(30000);
        out = QString::fromLocal8Bit(p.readAll());
        return finished && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
    }

    QString m_bin;
    QStringList m_prefix;
    std::unique_ptr<QTemporaryDir> m_dir;
    bool m_running = false;
};

/// A plain QPSQL connection of the test's own.
class RawPostgres {
public:
    explicit RawPostgres(const trainer::records::PostgresConfig& c)
    {
        QSqlDatabase db = QSqlDatabase::addDatabase("QPSQL", "records-test-raw-pg");
        db.setHostName(c.host);
        db.setDatabaseName(c.database);
        db.setUserName(c.user);
        m_ok = db.open();
    }
    ~RawPostgres()
    {
        {
            QSqlDatabase db = QSqlDatabase::database("records-test-raw-pg", false);
            db.close();
        }
        QSqlDatabase::removeDatabase("records-test-raw-pg");
    }
    bool ok() const { return m_ok; }
    QVariant scalar(const QString& sql)
    {
        QSqlQuery q(QSqlDatabase::database("records-test-raw-pg", false));
        return q.exec(sql) && q.next() ? q.value(0) : QVariant();
    }

private:
    bool m_ok = false;
};

}  // namespace padrob_test
