// trainer_tests: GoogleTest with a QCoreApplication, so that QSerialPort, QTimer and
// queued signals have an event loop to run in (tests spin it with
// QCoreApplication::processEvents or QTest-style waits of their own).
#include <QCoreApplication>

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setOrganizationName("padrob-tests");
    QCoreApplication::setApplicationName("trainer_tests");
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
