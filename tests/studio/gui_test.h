#pragma once
// What the studio's GUI tests share: where screenshots go, and letting the window settle.

#include <QApplication>
#include <QDir>
#include <QString>
#include <QTest>

namespace studio::test {

/// build/…/screenshots/<name> (the folder is made when missing).
inline QString screenshotPath(const QString& name)
{
    const QString dir = QStringLiteral(PADROB_SCREENSHOT_DIR);
    QDir().mkpath(dir);
    return dir + QLatin1Char('/') + name;
}

/// Waits `ms` and runs the pending events (paints, queued signals).
inline void settle(int ms = 300)
{
    QTest::qWait(ms);
    QApplication::processEvents();
}

}  // namespace studio::test
