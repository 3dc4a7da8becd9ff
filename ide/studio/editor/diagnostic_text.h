#pragma once
// How the editor shows a solver::Diagnostic: severity names, colours and icons,
// and the text a person reads. The solver keeps each message and hint as a
// translatable text (solver/core/diagnostic.h); this is the one place where they become
// GUI text, in the current language (ide/i18n/diagnostic_text.h). Every function gives
// the text of the language installed when it is called.

#include "solver/core/diagnostic.h"

#include <QColor>
#include <QIcon>
#include <QString>

namespace studio {

/// "Error", "Warning", "Note" (translated).
QString severityText(solver::Severity severity);
/// Red for errors, amber for warnings, blue for notes.
QColor severityColor(solver::Severity severity);
/// A small round icon in the severity's colour.
QIcon severityIcon(solver::Severity severity);

/// The message and hint as shown, in the current language (i18n::message, i18n::hint).
QString diagnosticMessage(const solver::Diagnostic& d);
QString diagnosticHint(const solver::Diagnostic& d);
/// "12:5", or "" for a diagnostic without a position.
QString diagnosticLocation(const solver::Diagnostic& d);
/// Rich text for a tooltip: severity, message, hint and code (HTML-escaped).
QString diagnosticToolTip(const solver::Diagnostic& d);

}  // namespace studio
