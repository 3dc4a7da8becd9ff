#include "trainer/io/user_folders.h"

#include <QStandardPaths>

namespace trainer::userFolders {

namespace {

QString data(const char* name)
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QLatin1Char('/') + QLatin1String(name);
}

}  // namespace

QString recordsDatabase() { return data("records.sqlite"); }
QString pendingAttempts() { return data("pending-attempts"); }
QString attemptInput() { return data("attempt-input"); }
QString demonstrations() { return data("demonstrations"); }
QString recovery() { return data("recovery"); }

QString stationProfiles()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppConfigLocation) + QStringLiteral("/station-profiles");
}

}  // namespace trainer::userFolders
