#include "ide/studio/model/model_bundle.h"

#include <atomic>

namespace studio {

std::shared_ptr<const ModelBundle> makeBundle(const QString& text, const QString& filePath,
                                              solver::Diagnostics& diagnostics)
{
    const std::string name = filePath.isEmpty() ? std::string("<untitled>") : filePath.toStdString();
    auto compiled = std::make_shared<const solver::CompiledModel>(solver::compileText(text.toStdString(), name));
    diagnostics.append(compiled->diagnostics);
    return makeBundle(std::move(compiled), filePath);
}

std::shared_ptr<const ModelBundle> makeBundleFromFile(const QString& filePath, solver::Diagnostics& diagnostics)
{
    auto compiled = std::make_shared<const solver::CompiledModel>(solver::compileFile(filePath.toStdString()));
    diagnostics.append(compiled->diagnostics);
    return makeBundle(std::move(compiled), filePath);
}

std::shared_ptr<const ModelBundle> makeBundle(std::shared_ptr<const solver::CompiledModel> compiled,
                                              const QString& filePath)
{
    static std::atomic<quint64> counter{0};
    if (!compiled || !compiled->model) return nullptr;  // a model is set only without errors
    auto bundle = std::make_shared<ModelBundle>();
    bundle->model = compiled->model;
    bundle->compiled = std::move(compiled);
    bundle->filePath = filePath;
    bundle->serial = ++counter;
    return bundle;
}

std::shared_ptr<const ModelBundle> bundleInScene(const std::shared_ptr<const ModelBundle>& model,
                                                 const ModelBundle* scene, solver::Diagnostics& diagnostics)
{
    if (!model || !scene || !model->model->contact) return model;
    auto compiled = std::make_shared<const solver::CompiledModel>(solver::compileSpec(model->spec(), &scene->spec()));
    diagnostics.append(compiled->diagnostics);
    return makeBundle(std::move(compiled), model->filePath);
}

}  // namespace studio
