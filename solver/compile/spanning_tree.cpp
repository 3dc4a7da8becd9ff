#include "solver/compile/spanning_tree.h"

#include <algorithm>
#include <deque>
#include <numeric>
#include <unordered_map>

namespace solver {

namespace {

// union-find over body indices, with path halving
class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : m_parent(n)
    {
        std::iota(m_parent.begin(), m_parent.end(), 0);
    }

    int find(int x)
    {
        while (m_parent[x] != x) {
            m_parent[x] = m_parent[m_parent[x]];
            x = m_parent[x];
        }
        return x;
    }

    bool unite(int a, int b)
    {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        m_parent[std::max(a, b)] = std::min(a, b);
        return true;
    }

private:
    std::vector<int> m_parent;
};

}  // namespace

std::vector<bool> buildSpanningTree(const ModelSpec& spec, Topology& topo)
{
    // body indices: ground first, then the written bodies in file order
    topo.bodyIds.assign(1, 0);
    std::unordered_map<int, int> indexOfId{{0, 0}};
    for (const BodySpec& b : spec.bodies) {
        if (indexOfId.count(b.id)) continue;  // ground or a duplicate (reported elsewhere)
        indexOfId[b.id] = static_cast<int>(topo.bodyIds.size());
        topo.bodyIds.push_back(b.id);
    }
    const std::size_t nb = topo.bodyIds.size();
    const std::size_t nj = spec.joints.size();

    auto bodyIndex = [&](int id) {
        auto it = indexOfId.find(id);
        return it == indexOfId.end() ? -1 : it->second;
    };
    topo.side1Body.resize(nj);
    topo.side2Body.resize(nj);
    for (std::size_t j = 0; j < nj; ++j) {
        topo.side1Body[j] = bodyIndex(spec.joints[j].side1.body);
        topo.side2Body[j] = bodyIndex(spec.joints[j].side2.body);
    }

    // priority: driven joints first, then file order
    std::vector<int> order(nj);
    std::iota(order.begin(), order.end(), 0);
    auto driven = [&](int j) {
        return std::any_of(spec.drives.begin(), spec.drives.end(),
                           [&](const DriveSpec& d) { return d.joint == spec.joints[j].id; });
    };
    std::stable_partition(order.begin(), order.end(), driven);
    // free joints (T 3) before all: their body is reached through them, never a loop's
    std::stable_partition(order.begin(), order.end(), [&](int j) { return spec.joints[j].type == JointType::Free; });

    // union-find: tree joints join groups, the others close loops
    DisjointSets sets(nb);
    std::vector<bool> isTree(nj, false), isCut(nj, false);
    std::vector<std::vector<int>> adjacent(nb);  // tree joints at each body, in priority order
    for (int j : order) {
        const int b1 = topo.side1Body[j], b2 = topo.side2Body[j];
        if (b1 < 0 || b2 < 0 || b1 == b2) continue;
        if (sets.unite(b1, b2)) {
            isTree[j] = true;
            adjacent[b1].push_back(j);
            adjacent[b2].push_back(j);
        } else {
            isCut[j] = true;
        }
    }

    // orient the tree: breadth-first from ground
    topo.parentBody.assign(nb, -1);
    topo.parentJoint.assign(nb, -1);
    topo.reversed.assign(nj, false);
    topo.treeJoints.clear();
    std::vector<bool> reached(nb, false);
    std::vector<std::vector<int>> children(nb);  // child tree joints per body
    reached[0] = true;
    std::deque<int> queue{0};
    while (!queue.empty()) {
        const int b = queue.front();
        queue.pop_front();
        for (int j : adjacent[b]) {
            const bool fromSide2 = topo.side2Body[j] == b;
            const int other = fromSide2 ? topo.side1Body[j] : topo.side2Body[j];
            if (reached[other]) continue;
            reached[other] = true;
            topo.parentBody[other] = b;
            topo.parentJoint[other] = j;
            topo.reversed[j] = fromSide2;
            topo.treeJoints.push_back(j);
            children[b].push_back(j);
            queue.push_back(other);
        }
    }

    // cut joints between reached bodies, in file order
    topo.loopJoints.clear();
    for (std::size_t j = 0; j < nj; ++j) {
        if (isCut[j] && reached[topo.side1Body[j]]) topo.loopJoints.push_back(static_cast<int>(j));
    }

    // serial chains: split at ground and at bodies with more than one child joint
    topo.chains.clear();
    auto childOf = [&](int j) { return topo.reversed[j] ? topo.side1Body[j] : topo.side2Body[j]; };
    for (int j : topo.treeJoints) {
        const int parent = topo.parentBody[childOf(j)];
        if (parent != 0 && children[parent].size() == 1) continue;  // continues a chain
        std::vector<int> chain{j};
        int b = childOf(j);
        while (children[b].size() == 1) {
            chain.push_back(children[b].front());
            b = childOf(children[b].front());
        }
        topo.chains.push_back(std::move(chain));
    }
    return reached;
}

}  // namespace solver
