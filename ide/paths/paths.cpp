#include "ide/paths/paths.h"

#include <QCoreApplication>
#include <QDir>

namespace paths {

namespace {

/// `relative` to the executable's folder, canonical when it exists.
QString besideExecutable(const QString& relative)
{
    const QDir dir(QCoreApplication::applicationDirPath() + QLatin1Char('/') + relative);
    return dir.exists() ? dir.canonicalPath() : QDir::cleanPath(dir.absolutePath());
}

}  // namespace

QString modelsDir() { return besideExecutable(QStringLiteral("../share/padrob/models")); }

QString tutorialsDir() { return besideExecutable(QStringLiteral("../share/padrob/resources/tutorials")); }

QString scenesDir() { return besideExecutable(QStringLiteral("../share/padrob/resources/scenes")); }

QString docsDir() { return besideExecutable(QStringLiteral("../share/doc/padrob")); }

QString defaultModel() { return modelsDir() + QStringLiteral("/liner_manipulator_fluid.pad"); }

}  // namespace paths
