// padrob-studio [MODEL]: the application (see app/main_window.h).
#include "ide/studio/app/main_window.h"
#include "ide/studio/view/viewport.h"

#include <QApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSurfaceFormat>
#include <QTranslator>

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(studio::Viewport::surfaceFormat());  // OpenGL 3.3 core, before the app
    QApplication app(argc, argv);
    QApplication::setOrganizationName("Padrob");
    QApplication::setApplicationName("padrob-studio");
    QApplication::setApplicationVersion(PADROB_VERSION);
    // the system's language (Spanish or English; the settings will choose it too)
    QTranslator qtTranslator, translator;
    if (qtTranslator.load(QLocale(), "qtbase", "_", QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QApplication::installTranslator(&qtTranslator);
    }
    if (translator.load(QLocale(), "padrob", "_", ":/i18n")) QApplication::installTranslator(&translator);
    studio::MainWindow window;
    const QStringList args = QApplication::arguments();
    window.openInitial(args.size() > 1 ? args.at(1) : QString());
    window.show();
    return QApplication::exec();
}
