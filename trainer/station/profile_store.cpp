#include "trainer/station/profile_store.h"

#include "trainer/io/read_file.h"
#include "trainer/io/user_folders.h"

#include "solver/core/output_file.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>

namespace trainer {

namespace {

/// The translation context of this file's messages (lupdate reads Tr::tr).
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(trainer::ProfileStore)
};

bool readProfile(const QString& path, StationProfile& out, QList<ProfileIssue>& issues)
{
    QString error;
    const std::optional<QByteArray> text =
        readLimitedFile(path, kMaxProfileBytes, solver::trText("Tutorials", "a station profile"), ".json",
                        solver::trText("Tutorials", "a station profile is a short JSON file; check that this is one"), &error);
    if (!text) {
        issues.append({path, error, true});
        return false;
    }
    QList<ProfileIssue> found;
    if (!StationProfile::fromJson(*text, out, found)) {
        for (ProfileIssue& i : found) i.where = i.where.isEmpty() ? path : path + ": " + i.where;
        issues += found;
        return false;
    }
    out.source = path;
    return true;
}

bool writeFile(const QString& path, const QByteArray& data, QString* error)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    // replaced whole, on the disk, or left as it was (solver/core/output_file.h)
    solver::Text writeError;
    if (!solver::writeWholeFile(path.toStdString(), data.toStdString(), {}, writeError)) {
        if (error) *error = translated(writeError);
        return false;
    }
    return true;
}

}  // namespace

ProfileStore::ProfileStore(QString root) : m_root(root.isEmpty() ? defaultRoot() : std::move(root)) {}

QString ProfileStore::defaultRoot()
{
    return userFolders::stationProfiles();
}

QString ProfileStore::modelKey(const QString& modelPath)
{
    return QFileInfo(modelPath).completeBaseName();
}

QString ProfileStore::fileNameFor(const QString& name)
{
    QString n = name.trimmed();
    for (QChar& c : n)
        if (c.unicode() < 32 || QStringLiteral("/\\:*?\"<>|").contains(c)) c = '_';
    if (n.isEmpty() || n.startsWith('.')) n.prepend("profile");
    return n + ".json";
}

QString ProfileStore::userFolder(const QString& modelPath) const
{
    return m_root + "/" + modelKey(modelPath);
}

QString ProfileStore::shippedFolder(const QString& modelPath)
{
    const QFileInfo fi(modelPath);
    return fi.absolutePath() + "/" + fi.completeBaseName() + ".station";
}

QList<StoredProfile> ProfileStore::list(const QString& modelPath) const
{
    QList<StoredProfile> user, shipped;
    auto scan = [](const QString& folder, bool isShipped, QList<StoredProfile>& out) {
        const QDir dir(folder);
        for (const QFileInfo& fi : dir.entryInfoList({"*.json"}, QDir::Files, QDir::Name)) {
            StoredProfile s;
            s.path = fi.absoluteFilePath();
            s.shipped = isShipped;
            StationProfile p;
            QList<ProfileIssue> issues;
            if (readProfile(s.path, p, issues)) {
                s.name = p.name;
                s.label = p.localized(p.name);
            } else {
                s.name = s.label = fi.completeBaseName();
                s.readable = false;
                s.problem = issues.isEmpty() ? QString() : issues.first().text();
            }
            out.append(s);
        }
    };
    scan(userFolder(modelPath), false, user);
    scan(shippedFolder(modelPath), true, shipped);
    for (const StoredProfile& s : shipped)
        if (std::none_of(user.begin(), user.end(), [&](const StoredProfile& u) { return u.name == s.name; }))
            user.append(s);
    return user;
}

bool ProfileStore::load(const QString& modelPath, const QString& name, StationProfile& out,
                        QList<ProfileIssue>& issues) const
{
    for (const StoredProfile& s : list(modelPath)) {
        if (s.name != name) continue;
        return readProfile(s.path, out, issues);
    }
    issues.append({{}, Tr::tr("there is no profile “%1” for %2").arg(name, modelKey(modelPath)), true});
    return false;
}

bool ProfileStore::resolve(const QString& modelPath, const QString& nameOrFile, const QList<DriveInfo>& drives,
                           StationProfile& out, QList<ProfileIssue>& issues) const
{
    if (nameOrFile.isEmpty()) {
        out = StationProfile::defaultFor(modelKey(modelPath), drives);
        return true;
    }
    if (QFileInfo(nameOrFile).isFile()) return readProfile(nameOrFile, out, issues);
    return load(modelPath, nameOrFile, out, issues);
}

bool ProfileStore::save(const QString& modelPath, const StationProfile& profile, SaveMode mode, QString* error) const
{
    if (profile.name.trimmed().isEmpty()) {
        if (error) *error = Tr::tr("a profile needs a name");
        return false;
    }
    const QString path = userFolder(modelPath) + "/" + fileNameFor(profile.name);
    if (QFileInfo::exists(path)) {
        if (mode == SaveMode::CreateOnly) {
            if (error) *error = Tr::tr("a profile named “%1” exists already").arg(profile.name);
            return false;
        }
        StationProfile old;
        QList<ProfileIssue> issues;
        if (!readProfile(path, old, issues)) {
            // unreadable (corrupt, newer): keep it aside, never lose it
            const QString aside = path + ".bak-" + QDateTime::currentDateTime().toString("yyyyMMdd-hhmmss");
            if (!QFile::rename(path, aside)) {
                if (error) *error = Tr::tr("cannot keep the old %1 aside; nothing was saved").arg(path);
                return false;
            }
        }
    }
    StationProfile p = profile;
    p.model = modelKey(modelPath);
    return writeFile(path, p.toJson(), error);
}

bool ProfileStore::remove(const QString& modelPath, const QString& name, QString* error) const
{
    for (const StoredProfile& s : list(modelPath)) {
        if (s.name != name) continue;
        if (s.shipped) {
            if (error) *error = Tr::tr("“%1” ships with the model and cannot be deleted").arg(name);
            return false;
        }
        if (!QFile::remove(s.path)) {
            if (error) *error = Tr::tr("cannot delete %1").arg(s.path);
            return false;
        }
        return true;
    }
    if (error) *error = Tr::tr("there is no profile “%1”").arg(name);
    return false;
}

QString ProfileStore::importFile(const QString& file, const QString& modelPath, QList<ProfileIssue>& issues) const
{
    StationProfile p;
    if (!readProfile(file, p, issues)) return {};
    QStringList taken;
    for (const StoredProfile& s : list(modelPath)) taken.append(s.name);
    const QString base = p.name.trimmed().isEmpty() ? QFileInfo(file).completeBaseName() : p.name.trimmed();
    QString name = base;
    for (int n = 2; taken.contains(name) || QFileInfo::exists(userFolder(modelPath) + "/" + fileNameFor(name)); ++n)
        name = QStringLiteral("%1 (%2)").arg(base).arg(n);
    p.name = name;
    QString error;
    if (!save(modelPath, p, SaveMode::CreateOnly, &error)) {
        issues.append({file, error, true});
        return {};
    }
    return name;
}

bool ProfileStore::exportFile(const StationProfile& profile, const QString& file, bool overwrite, QString* error)
{
    if (!overwrite && QFileInfo::exists(file)) {
        if (error) *error = Tr::tr("%1 exists already").arg(file);
        return false;
    }
    return writeFile(file, profile.toJson(), error);
}

}  // namespace trainer
