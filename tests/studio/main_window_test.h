#pragma once
// What the tests of the whole window (MainWindow) share: opening a model and waiting
// until it is applied, and choosing the UI's language as a user does.

#include "ide/i18n/language.h"
#include "ide/studio/app/main_window.h"
#include "tests/studio/gui_test.h"

#include <QAction>
#include <QTest>

namespace studio::test {

/// Opens a model and waits until it is applied (the editor checks it on a worker thread).
inline bool openAndWait(MainWindow& w, const QString& path)
{
    const quint64 before = w.bundle() ? w.bundle()->serial : 0;
    if (!w.openFile(path)) return false;
    return QTest::qWaitFor([&] { return w.bundle() && w.bundle()->serial != before; }, 10000);
}

/// Settings ▸ Language ▸ `code`, as the user picks it.
inline void chooseLanguage(MainWindow& w, const QString& code)
{
    auto* action = w.findChild<QAction*>("Language_" + code);
    QVERIFY(action);
    action->trigger();
    QCOMPARE(i18n::current(), code);
    settle(100);  // the LanguageChange events are posted
}

}  // namespace studio::test
