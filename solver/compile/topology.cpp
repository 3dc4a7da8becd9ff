#include "solver/compile/topology.h"

#include "solver/compile/spanning_tree.h"

#include <algorithm>
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

// a free joint (T 3) must carry its B2 from B1: a tree joint, run from side 1 to side 2
void checkFreeJoints(const ModelSpec& spec, const Topology& topo, Diagnostics& diags)
{
    for (std::size_t j = 0; j < spec.joints.size(); ++j) {
        const JointSpec& joint = spec.joints[j];
        if (joint.type != JointType::Free || !joint.side1.present || !joint.side2.present) continue;
        const Text who = trText("Diagnostics", "joint %1").with(std::to_string(joint.id) + quoted(joint.name));
        // in a loop: the cut joint itself, or on the tree path of a cut joint's loop (from
        // either of its bodies to their common ancestor)
        bool inLoop = false;
        for (int c : topo.loopJoints) {
            if (c == static_cast<int>(j)) inLoop = true;
            std::vector<int> path1, path2;
            for (int b = topo.side1Body[c]; b > 0; b = topo.parentBody[b]) path1.push_back(topo.parentJoint[b]);
            for (int b = topo.side2Body[c]; b > 0; b = topo.parentBody[b]) path2.push_back(topo.parentJoint[b]);
            const auto on = [&](const std::vector<int>& p) { return std::find(p.begin(), p.end(), j) != p.end(); };
            if (on(path1) != on(path2)) inLoop = true;
        }
        if (inLoop) {
            diags.error("free-joint-in-loop", joint.src.pos,
                        trText("Diagnostics", "%1 is a free joint (T 3), but its body B2 is also held by other joints "
                                              "(a closed loop)")
                            .with(who),
                        trText("Diagnostics", "a free body moves only through its free joint: remove the other joints "
                                              "between it and the rest, or use T 0, T 1 or T 2"));
        } else if (topo.reversed.size() > j && topo.reversed[j]) {
            diags.error("free-joint-reversed", joint.side2.src.where("B"),
                        trText("Diagnostics", "%1 is a free joint (T 3) whose B2 is nearer the ground than its B1")
                            .with(who),
                        trText("Diagnostics", "write the free joint from the side nearer the ground (B1, usually "
                                              "body 0) to the free body (B2)"));
        }
    }
}

}  // namespace

Topology analyzeTopology(const ModelSpec& spec, Diagnostics& diags)
{
    Topology topo;
    const std::vector<bool> reached = buildSpanningTree(spec, topo);
    checkConnected(spec, topo, reached, diags);
    checkFreeJoints(spec, topo, diags);
    // one entry per compiled coordinate: a free joint's six
    std::vector<int> expanded;
    expanded.reserve(topo.treeJoints.size());
    for (int j : topo.treeJoints) {
        const int copies = spec.joints[static_cast<std::size_t>(j)].type == JointType::Free ? kFreeJointCoordinates : 1;
        expanded.insert(expanded.end(), static_cast<std::size_t>(copies), j);
    }
    topo.treeJoints = std::move(expanded);
    return topo;
}

}  // namespace solver
