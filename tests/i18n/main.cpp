// i18n_tests: GoogleTest with a QCoreApplication (translators need one).
#include <QCoreApplication>

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setOrganizationName("padrob-tests");
    QCoreApplication::setApplicationName("i18n_tests");
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
