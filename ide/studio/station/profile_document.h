#pragma once
// ProfileDocument: the station profile the Station workspace edits, apart from the page
// that shows it (docs/studio.md, "Station"). It knows the model's stored profiles (the
// user's and those shipped with the model), the profile being edited, where it came
// from, whether it has unsaved edits, and does the file work: open, new, save under a
// name, delete, import, export. It asks nobody anything: where a person must agree
// (replacing a file, dropping edits) the page asks first and then tells the document what
// to do. No widgets; errors come back as sentences for the page to show.

#include "trainer/station/profile.h"
#include "trainer/station/profile_store.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QList>
#include <QString>

namespace studio {

class ProfileDocument {
    Q_DECLARE_TR_FUNCTIONS(studio::ProfileDocument)
public:
    enum class Origin { Unsaved, User, Shipped };

    /// Where user profiles are kept.
    void setStore(const trainer::ProfileStore& store) { m_store = store; }
    const trainer::ProfileStore& store() const { return m_store; }
    /// The model whose profiles are listed (profiles are per model file); lists them.
    void setModelPath(const QString& modelPath);
    const QString& modelPath() const { return m_modelPath; }
    /// Reads the list of the model's profiles again.
    void relist();
    const QList<trainer::StoredProfile>& stored() const { return m_stored; }

    const trainer::StationProfile& profile() const { return m_profile; }
    /// The profile to change in place (the caller marks it dirty: setDirty()).
    trainer::StationProfile& edit() { return m_profile; }
    Origin origin() const { return m_origin; }
    /// The name it is stored under (User, Shipped).
    const QString& storedName() const { return m_storedName; }
    bool isDirty() const { return m_dirty; }
    /// False when nothing changed.
    bool setDirty(bool dirty);
    void setCurrent(const trainer::StationProfile& profile, Origin origin, const QString& storedName, bool dirty);

    /// Opens `preferred` when it can, else the first readable profile, else the model's
    /// default profile (StationProfile::defaultFor, not saved).
    void openFirst(const QString& preferred, const QList<trainer::DriveInfo>& drives);
    /// Opens a stored profile; false with `error` (the current one stays).
    bool open(const QString& name, QString* error);
    /// A new, unsaved profile with one bank.
    void makeNew(const QString& name, const QString& bankName);

    /// The user's file of the profile named `name`.
    QString userFile(const QString& name) const;
    /// Whether Save must ask before writing under the profile's own name: not when it
    /// is its own user file, untouched since it was read or written.
    bool saveMustAsk() const;
    /// Whether writing under `name` would replace a file.
    bool exists(const QString& name) const;
    /// Saves the profile under `name` in the user's folder (it becomes that stored
    /// profile, not dirty); `replace`: a file there may be replaced. False with `error`.
    bool saveUnder(const QString& name, bool replace, QString* error);
    /// Deletes the user profile shown. False with `error`.
    bool remove(QString* error);
    /// Imports a profile file into the store: its stored name, or "" with `error`.
    QString importFile(const QString& file, QString* error);
    /// Writes the profile to `file`. False with `error`.
    bool exportTo(const QString& file, bool replace, QString* error) const;

private:
    trainer::ProfileStore m_store;
    QString m_modelPath;
    QList<trainer::StoredProfile> m_stored;
    trainer::StationProfile m_profile;
    Origin m_origin = Origin::Unsaved;
    QString m_storedName;
    QDateTime m_storedTime;  ///< the user file's time when read or written
    bool m_dirty = false;
};

}  // namespace studio
