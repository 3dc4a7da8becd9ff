#pragma once
// Where Padrob writes what belongs to its user, in one place (the bundled files, read
// only, are ide/paths/paths.h). Everything is under Qt's standard locations for the
// application (QStandardPaths; in tests, their test-mode folders):
//   <AppDataLocation>   (e.g. ~/.local/share/padrob)
//       records.sqlite       the trainee records (docs/records.md)
//       pending-attempts/    attempts the records refused, waiting to be brought in
//       attempt-input/       the operator's input of each live attempt (the last 20)
//       demonstrations/      the user's copies of the stages' demonstrations
//       recovery/            the editor's recovery copies of unsaved models
//   <AppConfigLocation> (e.g. ~/.config/padrob)
//       station-profiles/    the user's station profiles, a folder per model
// A folder is not made here: whoever writes into it makes it.

#include <QString>

namespace trainer::userFolders {

/// <AppDataLocation>/records.sqlite: the local records database.
QString recordsDatabase();
/// <AppDataLocation>/pending-attempts.
QString pendingAttempts();
/// <AppDataLocation>/attempt-input.
QString attemptInput();
/// <AppDataLocation>/demonstrations.
QString demonstrations();
/// <AppDataLocation>/recovery.
QString recovery();
/// <AppConfigLocation>/station-profiles.
QString stationProfiles();

}  // namespace trainer::userFolders
