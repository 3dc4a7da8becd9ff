#include "ide/studio/view/scene_file.h"

#include "ide/i18n/diagnostic_text.h"
#include "solver/pipeline.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>

namespace studio {

namespace {

constexpr int kShownDiagnostics = 5;

}  // namespace

SceneFile loadSceneFile(const QString& path)
{
    SceneFile out;
    const QString shown = QDir::toNativeSeparators(path);
    QFile f(path);
    if (!QFileInfo(path).isFile() || !f.open(QIODevice::ReadOnly)) {
        const QString why = QFileInfo::exists(path) ? f.errorString()
                                                    : QCoreApplication::translate("studio::SceneFile", "no such file");
        out.error = QCoreApplication::translate("studio::SceneFile", "Cannot read the scene %1: %2").arg(shown, why);
        return out;
    }
    if (f.size() > qint64(solver::kMaxModelFileBytes)) {
        out.error = QCoreApplication::translate("studio::SceneFile", "The scene %1 is too large (over %2 MB).")
                        .arg(shown)
                        .arg(solver::kMaxModelFileBytes >> 20);
        return out;
    }
    solver::Diagnostics diagnostics(path.toStdString());
    auto bundle = makeBundleFromFile(QFileInfo(path).absoluteFilePath(), diagnostics);
    if (!bundle) {
        QStringList lines;
        for (const solver::Diagnostic& d : diagnostics) {
            if (d.severity != solver::Severity::Error) continue;
            if (lines.size() == kShownDiagnostics) {
                lines << QStringLiteral("…");
                break;
            }
            lines << QString::fromStdString(i18n::format(d));  // in the current language
        }
        out.error = QCoreApplication::translate("studio::SceneFile", "The scene %1 has errors:\n%2")
                        .arg(shown, lines.join(QLatin1Char('\n')));
        return out;
    }
    const auto& graphics = bundle->spec().graphics;
    const auto ground = std::count_if(graphics.begin(), graphics.end(), [](const auto& g) { return g.body == 0; });
    if (ground == 0) {
        out.error = QCoreApplication::translate("studio::SceneFile",
                                                "The scene %1 has no ground graphics (G … B 0) to draw.")
                        .arg(shown);
        return out;
    }
    const auto skipped = static_cast<int>(graphics.size()) - static_cast<int>(ground);
    if (skipped > 0) {
        out.note = QCoreApplication::translate("studio::SceneFile",
                                               "%n graphic(s) on moving bodies of the scene are not drawn.", nullptr,
                                               skipped);
    }
    out.bundle = std::move(bundle);
    return out;
}

}  // namespace studio
