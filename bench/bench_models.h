#pragma once
// The models and states the benchmarks run on: example files from models/ and
// generated chains and trees (bench/generate.h), compiled once per process.

#include "solver/core/model.h"
#include "solver/core/state.h"
#include "solver/integrate/simulation.h"
#include "bench/generate.h"
#include "solver/pipeline.h"

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace bench {

/// The text of models/<name>.
inline std::string exampleText(const std::string& name)
{
    const std::string path = std::string(PADROB_SOURCE_DIR) + "/models/" + name;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Loads and compiles model text; throws when it has errors.
inline std::shared_ptr<const solver::Model> compileText(const std::string& text, const std::string& file)
{
    auto model = solver::compileText(text, file).model;
    if (!model) throw std::runtime_error(file + " does not compile");
    return model;
}

/// models/<name>, compiled once.
inline std::shared_ptr<const solver::Model> example(const std::string& name)
{
    static std::map<std::string, std::shared_ptr<const solver::Model>> cache;
    auto& m = cache[name];
    if (!m) m = compileText(exampleText(name), name);
    return m;
}

/// A generated chain or binary tree of n bodies, compiled once.
inline std::shared_ptr<const solver::Model> generated(bool tree, int n)
{
    static std::map<std::pair<bool, int>, std::shared_ptr<const solver::Model>> cache;
    auto& m = cache[{tree, n}];
    if (!m) {
        m = compileText(tree ? treeModelText(n) : chainModelText(n), tree ? "tree.pad" : "chain.pad");
    }
    return m;
}

/// The initial state with the command 0.5 on every drive, after the simulation's
/// mode rules (as `padrob bench` times the forward dynamics).
inline solver::State drivenState(const std::shared_ptr<const solver::Model>& model)
{
    solver::Simulation sim(model, solver::SimulationOptions{});
    for (int j = 0; j < model->nb; ++j) {
        if (model->drive[j].type != solver::DriveType::None) sim.setCommand(j, 0.5);
    }
    std::vector<solver::SimulationEvent> events;
    std::string error;
    sim.advanceTo(0.0, events, error);
    return sim.state();
}

/// The operator of the step benchmarks: u = 0.8 sin(2π 0.5 t + φ) on every drive.
inline void sineCommands(solver::Simulation& sim, double t)
{
    const solver::Model& m = sim.model();
    int k = 0, drives = 0;
    for (int j = 0; j < m.nb; ++j) drives += m.drive[j].type != solver::DriveType::None ? 1 : 0;
    for (int j = 0; j < m.nb; ++j) {
        if (m.drive[j].type == solver::DriveType::None) continue;
        const double phase = 2 * std::numbers::pi * k++ / drives;
        sim.setCommand(j, 0.8 * std::sin(2 * std::numbers::pi * 0.5 * t + phase));
    }
}

}  // namespace bench
