#include "ide/studio/station/profile_document.h"

#include <QFileInfo>
#include <QStringList>

#include <algorithm>

namespace studio {

namespace {

QString issuesText(const QList<trainer::ProfileIssue>& issues)
{
    QStringList lines;
    for (const trainer::ProfileIssue& i : issues) lines << i.text();
    return lines.join(QStringLiteral("; "));
}

}  // namespace

void ProfileDocument::setModelPath(const QString& modelPath)
{
    m_modelPath = modelPath;
    relist();
}

void ProfileDocument::relist()
{
    m_stored = m_modelPath.isEmpty() ? QList<trainer::StoredProfile>{} : m_store.list(m_modelPath);
}

bool ProfileDocument::setDirty(bool dirty)
{
    if (m_dirty == dirty) return false;
    m_dirty = dirty;
    return true;
}

void ProfileDocument::setCurrent(const trainer::StationProfile& profile, Origin origin, const QString& storedName,
                                 bool dirty)
{
    m_profile = profile;
    m_origin = origin;
    m_storedName = storedName;
    m_storedTime = origin == Origin::User ? QFileInfo(userFile(storedName)).lastModified() : QDateTime();
    m_dirty = dirty;
}

void ProfileDocument::openFirst(const QString& preferred, const QList<trainer::DriveInfo>& drives)
{
    QStringList order;
    if (!preferred.isEmpty()) order << preferred;
    for (const trainer::StoredProfile& s : m_stored)
        if (s.readable) order << s.name;
    for (const QString& name : order) {
        const auto s = std::find_if(m_stored.begin(), m_stored.end(),
                                    [&](const trainer::StoredProfile& s) { return s.name == name && s.readable; });
        if (s == m_stored.end()) continue;
        trainer::StationProfile p;
        QList<trainer::ProfileIssue> issues;
        if (!m_store.load(m_modelPath, name, p, issues)) continue;
        setCurrent(p, s->shipped ? Origin::Shipped : Origin::User, name, false);
        return;
    }
    setCurrent(trainer::StationProfile::defaultFor(trainer::ProfileStore::modelKey(m_modelPath), drives),
               Origin::Unsaved, {}, false);
}

bool ProfileDocument::open(const QString& name, QString* error)
{
    trainer::StationProfile p;
    QList<trainer::ProfileIssue> issues;
    relist();
    if (!m_store.load(m_modelPath, name, p, issues)) {
        *error = tr("Cannot open the profile “%1”: %2").arg(name, issuesText(issues));
        return false;
    }
    const auto s = std::find_if(m_stored.begin(), m_stored.end(),
                                [&](const trainer::StoredProfile& s) { return s.name == name; });
    setCurrent(p, s != m_stored.end() && s->shipped ? Origin::Shipped : Origin::User, name, false);
    return true;
}

void ProfileDocument::makeNew(const QString& name, const QString& bankName)
{
    trainer::StationProfile p;
    p.name = name;
    p.model = trainer::ProfileStore::modelKey(m_modelPath);
    p.banks.append(trainer::Bank{bankName, {}, {}});
    setCurrent(p, Origin::Unsaved, {}, true);
}

QString ProfileDocument::userFile(const QString& name) const
{
    return m_store.root() + QLatin1Char('/') + trainer::ProfileStore::modelKey(m_modelPath) + QLatin1Char('/') +
           trainer::ProfileStore::fileNameFor(name);
}

bool ProfileDocument::saveMustAsk() const
{
    if (m_origin != Origin::User || m_profile.name != m_storedName) return true;
    // its own file, unless someone else changed it meanwhile
    const QFileInfo file(userFile(m_storedName));
    return !(file.exists() && file.lastModified() == m_storedTime);
}

bool ProfileDocument::exists(const QString& name) const { return QFileInfo::exists(userFile(name)); }

bool ProfileDocument::saveUnder(const QString& name, bool replace, QString* error)
{
    trainer::StationProfile p = m_profile;
    p.name = name;
    p.model = trainer::ProfileStore::modelKey(m_modelPath);
    const QString path = userFile(name);
    const auto mode = replace && QFileInfo::exists(path) ? trainer::ProfileStore::SaveMode::Overwrite
                                                          : trainer::ProfileStore::SaveMode::CreateOnly;
    if (!m_store.save(m_modelPath, p, mode, error)) return false;
    relist();
    m_profile = p;
    m_origin = Origin::User;
    m_storedName = name;
    m_storedTime = QFileInfo(path).lastModified();
    return true;
}

bool ProfileDocument::remove(QString* error)
{
    if (m_origin != Origin::User) return false;
    return m_store.remove(m_modelPath, m_storedName, error);
}

QString ProfileDocument::importFile(const QString& file, QString* error)
{
    QList<trainer::ProfileIssue> issues;
    const QString name = m_store.importFile(file, m_modelPath, issues);
    if (name.isEmpty()) {
        *error = tr("Cannot import %1: %2").arg(QFileInfo(file).fileName(), issuesText(issues));
        return {};
    }
    relist();
    return name;
}

bool ProfileDocument::exportTo(const QString& file, bool replace, QString* error) const
{
    trainer::StationProfile p = m_profile;
    p.model = trainer::ProfileStore::modelKey(m_modelPath);
    return trainer::ProfileStore::exportFile(p, file, replace, error);
}

}  // namespace studio
