#include "ide/studio/model/model_bundle.h"

#include "solver/compile/compile.h"

#include <atomic>

namespace studio {

std::shared_ptr<const ModelBundle> makeBundle(const QString& text, const QString& filePath,
                                              solver::Diagnostics& diagnostics)
{
    static std::atomic<quint64> counter{0};
    const std::string name = filePath.isEmpty() ? std::string("<untitled>") : filePath.toStdString();
    auto loaded = std::make_shared<solver::CompiledModel>(solver::compileText(text.toStdString(), name));
    diagnostics.append(loaded->diagnostics);
    if (!loaded->ok() || !loaded->topology) return nullptr;
    solver::Diagnostics compileDiags(name);
    std::shared_ptr<const solver::Model> model = solver::compileLoaded(*loaded, compileDiags);
    diagnostics.append(compileDiags);
    if (!model) return nullptr;
    auto bundle = std::make_shared<ModelBundle>();
    bundle->loaded = std::move(loaded);
    bundle->model = std::move(model);
    bundle->filePath = filePath;
    bundle->serial = ++counter;
    return bundle;
}

}  // namespace studio
