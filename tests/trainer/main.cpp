// trainer_tests: GoogleTest with a QCoreApplication, so that QSerialPort, QTimer and
// queued signals have an event loop to run in (tests spin it with
// QCoreApplication::processEvents or QTest-style waits of their own).
#include <QCoreApplication>
#include <QLocale>

#include <gtest/gtest.h>

#include <clocale>

int main(int argc, char** argv)
{
    qunsetenv("LANGUAGE");  // the C library's messages (strerror) would follow it
    QCoreApplication app(argc, argv);
    QCoreApplication::setOrganizationName("padrob-tests");
    QCoreApplication::setApplicationName("trainer_tests");
    // QCoreApplication took the C library's locale from the environment: the tests compare
    // English texts and numbers with '.', so a developer's Spanish locale must not change
    // them (locale_test.cpp sets es_CL itself where it means to)
    if (!std::setlocale(LC_ALL, "C.UTF-8")) std::setlocale(LC_ALL, "C");
    QLocale::setDefault(QLocale::c());
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
