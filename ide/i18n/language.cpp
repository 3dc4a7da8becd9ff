#include "ide/i18n/language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

#include <memory>

// Q_INIT_RESOURCE must be used outside a namespace
static void initTranslationResources() { Q_INIT_RESOURCE(padrob_translations); }

namespace i18n {

namespace {

struct Installed {
    QString code = QStringLiteral("en");
    std::unique_ptr<QTranslator> qt, padrob;
};

Installed& installed()
{
    static Installed state;
    return state;
}

}  // namespace

QStringList languages() { return {QStringLiteral("es"), QStringLiteral("en")}; }

bool isLanguage(const QString& code) { return languages().contains(code); }

QString nativeName(const QString& code)
{
    if (code == QLatin1String("es")) return QStringLiteral("Español");
    if (code == QLatin1String("en")) return QStringLiteral("English");
    return code;
}

QString systemLanguage()
{
    const QStringList ui = QLocale::system().uiLanguages();
    const QString first = ui.isEmpty() ? QLocale::system().name() : ui.front();
    return first.startsWith(QLatin1String("es")) ? QStringLiteral("es") : QStringLiteral("en");
}

QLocale localeFor(const QString& code)
{
    if (code == QLatin1String("es")) return QLocale(QLocale::Spanish, QLocale::Chile);
    return QLocale(QLocale::English, QLocale::UnitedStates);
}

bool install(const QString& code)
{
    if (!isLanguage(code)) return false;
    Installed& state = installed();
    // the catalogues live in this static library; make sure they are registered
    initTranslationResources();
    auto padrob = std::make_unique<QTranslator>();
    auto qt = std::make_unique<QTranslator>();
    const QLocale locale = localeFor(code);
    const bool padrobLoaded = padrob->load(QStringLiteral(":/i18n/padrob_%1.qm").arg(code));
    const bool qtLoaded =
        code != QLatin1String("en") &&
        qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"), QLibraryInfo::path(QLibraryInfo::TranslationsPath));
    if (state.padrob) QCoreApplication::removeTranslator(state.padrob.get());
    if (state.qt) QCoreApplication::removeTranslator(state.qt.get());
    state.padrob.reset();
    state.qt.reset();
    QLocale::setDefault(locale);
    state.code = code;
    if (qtLoaded) {
        QCoreApplication::installTranslator(qt.get());
        state.qt = std::move(qt);
    }
    if (padrobLoaded) {
        QCoreApplication::installTranslator(padrob.get());  // sends QEvent::LanguageChange
        state.padrob = std::move(padrob);
    }
    return true;
}

QString current() { return installed().code; }

QString startLanguage(const QString& requested)
{
    if (isLanguage(requested)) return requested;
    const QString saved = QSettings().value(QStringLiteral("ui/language")).toString();
    if (isLanguage(saved)) return saved;
    return systemLanguage();
}

bool switchTo(const QString& code)
{
    if (!install(code)) return false;
    QSettings().setValue(QStringLiteral("ui/language"), code);
    return true;
}

std::string trStd(const char* context, const char* text, const char* disambiguation, int n)
{
    return QCoreApplication::translate(context, text, disambiguation, n).toStdString();
}

}  // namespace i18n
