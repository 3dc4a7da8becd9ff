// centre_tests: GoogleTest with a QCoreApplication (Qt's clocks, processes, files).
#include <QCoreApplication>
#include <QLocale>

#include <gtest/gtest.h>

#include <clocale>

int main(int argc, char** argv)
{
    qunsetenv("LANGUAGE");
    QCoreApplication app(argc, argv);
    if (!std::setlocale(LC_ALL, "C.UTF-8")) std::setlocale(LC_ALL, "C");
    QLocale::setDefault(QLocale::c());
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
