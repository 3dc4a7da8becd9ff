#pragma once
// The model layer's texts in the operator's language. The solver is Qt-free and keeps
// each diagnostic's message and hint as solver::Text (an English template with its
// arguments); these translate them with the installed catalogue (context
// "Diagnostics", filled by lupdate from the trText(…) calls), falling back to English.

#include "solver/core/diagnostic.h"

#include <QString>

#include <string>

namespace i18n {

/// A Text in the current language (its template and every phrase argument translated).
QString text(const solver::Text& t);
/// A diagnostic's message and hint in the current language (the English message for
/// one that has no translatable text).
QString message(const solver::Diagnostic& d);
QString hint(const solver::Diagnostic& d);
/// "error", "warning", "note" in the current language.
QString severityName(solver::Severity s);
/// "file:line:col: error: message [hint]" in the current language (the CLI's format).
std::string format(const solver::Diagnostic& d);

}  // namespace i18n
