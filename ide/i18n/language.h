#pragma once
// The language of the front ends: Spanish (Chile) or English.
//
// The translations (translations/padrob_*.ts, compiled by lrelease) are built into this
// library under :/i18n/. install() loads one language's catalogue and Qt's own, makes
// its locale the default (so numbers read 1,5 in Spanish) and sends every widget a
// QEvent::LanguageChange, so a running application changes language without a restart.
// Model files are not affected: the solver reads and writes them with '.' whatever the
// locale (docs/glossary.md, docs/architecture.md).

#include <QLocale>
#include <QString>
#include <QStringList>

#include <string>

namespace i18n {

/// The languages there are, as codes: {"es", "en"}.
QStringList languages();
/// True for a code in languages().
bool isLanguage(const QString& code);
/// The name of a language in that language: "Español", "English".
QString nativeName(const QString& code);
/// The language of the system's locale (LANGUAGE, LC_ALL, LC_MESSAGES, LANG): "es" for
/// any Spanish, otherwise "en".
QString systemLanguage();
/// The locale that shows numbers, dates and lists for a language: es_CL or en_US.
QLocale localeFor(const QString& code);
/// Installs `code`'s catalogues (replacing those of the previous call), makes its
/// locale the default and tells every object of the application. Returns false (and
/// installs nothing) for an unknown code.
bool install(const QString& code);
/// The language installed last ("en" before any install()).
QString current();
/// The language to start in: `requested` (a --lang option) when it is one, else the
/// one the settings remember (QSettings "ui/language", written by switchTo), else the
/// system's (first start).
QString startLanguage(const QString& requested = {});
/// install(code), and remember it in the settings for the next start (the operator's
/// choice in the Settings menu or on the kiosk's start screen).
bool switchTo(const QString& code);

/// QCoreApplication::translate(context, text) as UTF-8 for the Qt-free parts (the CLI
/// prints std::string). lupdate reads calls to it as `translate` (the
/// -tr-function-alias option in ide/CMakeLists.txt).
std::string trStd(const char* context, const char* text, const char* disambiguation = nullptr, int n = -1);

}  // namespace i18n
