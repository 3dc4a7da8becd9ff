#include "solver/compile/topology.h"

#include "solver/compile/spanning_tree.h"

#include <string>

namespace solver {

namespace {

std::string quoted(const std::string& name)
{
    return name.empty() ? std::string() : " \"" + name + "\"";
}

// bodies that ground does not reach
void checkConnected(const ModelSpec& spec, const Topology& topo, const std::vector<bool>& reached,
                    Diagnostics& diags)
{
    for (std::size_t b = 1; b < reached.size(); ++b) {
        if (reached[b]) continue;
        const BodySpec* body = spec.body(topo.bodyIds[b]);
        const Text who =
            trText("Diagnostics", "body %1").with(std::to_string(topo.bodyIds[b]) + quoted(body ? body->name : ""));
        diags.error("body-not-connected", body ? body->src.pos : SourcePos{},
                    trText("Diagnostics", "%1 is not connected to ground: no chain of joints leads from body 0 to it")
                        .with(who),
                    trText("Diagnostics", "add a joint (C) that connects it to ground or to a connected body"));
    }
}

}  // namespace

Topology analyzeTopology(const ModelSpec& spec, Diagnostics& diags)
{
    Topology topo;
    const std::vector<bool> reached = buildSpanningTree(spec, topo);
    checkConnected(spec, topo, reached, diags);
    return topo;
}

}  // namespace solver
