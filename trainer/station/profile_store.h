#pragma once
// Where station profiles live. Per model (the model file's base name, e.g.
// "liner_manipulator"):
//  - shipped profiles, read-only, next to the model: <model dir>/<base>.station/*.json
//    (the liner manipulator ships "Gamepad" and "Console (8 levers)");
//  - the user's, in <config>/station-profiles/<base>/<name>.json, where <config> is
//    QStandardPaths::AppConfigLocation (e.g. ~/.config/padrob) unless a root is given.
// A user profile with a shipped profile's name takes its place (editing a shipped
// profile saves a copy). When a model has no profile at all, StationProfile::defaultFor
// makes one.
//
// Nothing is ever silently overwritten: save() refuses an existing file unless told
// to overwrite (the GUI asks first), and an existing file that cannot be read
// (corrupt, from a newer Padrob) is kept aside as "<name>.json.bak-<time>" before it is
// replaced. Files are written through QSaveFile: complete or not at all.

#include "trainer/station/profile.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace trainer {

struct StoredProfile {
    QString name;
    QString label;  ///< the name as a person reads it (StationProfile::localized; read at list())
    QString path;
    bool shipped = false;  ///< read-only, next to the model
    bool readable = true;  ///< false: corrupt or from a newer version (`problem` says why)
    QString problem;
};

class ProfileStore {
public:
    /// `root`: the folder of user profiles ("" = the default under AppConfigLocation).
    explicit ProfileStore(QString root = {});
    QString root() const { return m_root; }
    static QString defaultRoot();

    /// The model's base name ("liner_manipulator" for ".../liner_manipulator.pad").
    static QString modelKey(const QString& modelPath);

    /// Every profile of the model, user ones first then shipped ones not shadowed,
    /// each by name (sorted).
    QList<StoredProfile> list(const QString& modelPath) const;
    /// Loads `name` (user first, then shipped). False with `issues` (a missing file, a
    /// corrupt one: where and why).
    bool load(const QString& modelPath, const QString& name, StationProfile& out, QList<ProfileIssue>& issues) const;

    /// The profile `nameOrFile` names for the model: a .json file, else one of the
    /// model's profiles (load()); "" the one Padrob makes for the model
    /// (StationProfile::defaultFor with `drives`). False with `issues`.
    bool resolve(const QString& modelPath, const QString& nameOrFile, const QList<DriveInfo>& drives,
                 StationProfile& out, QList<ProfileIssue>& issues) const;

    enum class SaveMode { CreateOnly, Overwrite };
    /// Saves under the profile's name in the user folder. CreateOnly: false (and
    /// `error`) when that name exists. Overwrite: replaces it, keeping an unreadable
    /// old file aside first.
    bool save(const QString& modelPath, const StationProfile& profile, SaveMode mode, QString* error = nullptr) const;
    /// Deletes a user profile (shipped ones cannot be deleted).
    bool remove(const QString& modelPath, const QString& name, QString* error = nullptr) const;

    /// Reads a profile file from anywhere and saves it for the model under its name,
    /// or "<name> (2)", "(3)"… when taken. Returns the name used, "" with `issues`.
    QString importFile(const QString& file, const QString& modelPath, QList<ProfileIssue>& issues) const;
    /// Writes `profile` to `file`; refuses an existing file unless `overwrite`.
    static bool exportFile(const StationProfile& profile, const QString& file, bool overwrite, QString* error = nullptr);

    /// The name saved profiles get on disk: the profile name with / \ : * ? " < > |
    /// and control characters replaced by '_'.
    static QString fileNameFor(const QString& name);

private:
    QString userFolder(const QString& modelPath) const;
    static QString shippedFolder(const QString& modelPath);
    QString m_root;
};

}  // namespace trainer
