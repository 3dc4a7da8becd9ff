#include "ide/i18n/diagnostic_text.h"

#include <QCoreApplication>

namespace i18n {

namespace {

std::string translate(const char* context, const char* tmpl)
{
    return QCoreApplication::translate(context, tmpl).toStdString();
}

}  // namespace

QString text(const solver::Text& t) { return QString::fromStdString(t.render(translate)); }

QString message(const solver::Diagnostic& d)
{
    return d.messageText.empty() ? QString::fromStdString(d.message) : text(d.messageText);
}

QString hint(const solver::Diagnostic& d)
{
    return d.hintText.empty() ? QString::fromStdString(d.hint) : text(d.hintText);
}

QString severityName(solver::Severity s)
{
    switch (s) {
    case solver::Severity::Error: return QCoreApplication::translate("Diagnostics", "error");
    case solver::Severity::Warning: return QCoreApplication::translate("Diagnostics", "warning");
    case solver::Severity::Note: return QCoreApplication::translate("Diagnostics", "note");
    }
    return QCoreApplication::translate("Diagnostics", "error");
}

std::string format(const solver::Diagnostic& d)
{
    std::string out = d.file.empty() ? std::string("<model>") : d.file;
    if (d.pos.valid()) out += ':' + std::to_string(d.pos.line) + ':' + std::to_string(d.pos.column);
    out += ": " + i18n::severityName(d.severity).toStdString() + ": " + message(d).toStdString();
    const std::string h = hint(d).toStdString();
    if (!h.empty()) out += " [" + h + ']';
    return out;
}

}  // namespace i18n
