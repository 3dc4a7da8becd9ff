#include "trainer/io/read_file.h"

#include "solver/core/text_file.h"

#include <QCoreApplication>

namespace trainer {

QString translated(const solver::Text& t)
{
    return QString::fromStdString(t.render([](const char* context, const char* tmpl) {
        return QCoreApplication::translate(context, tmpl).toStdString();
    }));
}

std::optional<QByteArray> readLimitedFile(const QString& path, std::uintmax_t maxBytes, const solver::Text& fileKind,
                                          const char* extension, const solver::Text& tooLargeHint, QString* error)
{
    solver::Diagnostics diags;
    std::optional<std::string> text = solver::readTextFile(path.toStdString(), maxBytes, fileKind, extension, tooLargeHint, diags);
    if (!text) {
        if (error && !diags.empty()) {
            const solver::Diagnostic& d = diags.items().front();
            *error = translated(d.messageText);
            if (!d.hintText.empty()) *error += " [" + translated(d.hintText) + "]";
        }
        return std::nullopt;
    }
    return QByteArray::fromStdString(*text);
}

}  // namespace trainer
