#include "bench/generate.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>
#include <vector>

namespace bench {

namespace {

/// The shortest text that reads back as v.
std::string num(double v)
{
    char buf[32];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
    (void)ec;
    return std::string(buf, p);
}

/// The model text of n links with parent[k] (0 = the ground) for k = 1 … n, parents
/// first; side[k] is the lateral offset of link k's joint on its parent (units of L).
std::string linksText(const std::string& title, int n, const std::vector<int>& parent, const std::vector<int>& depth,
                      const std::vector<double>& side, const GeneratedModelOptions& o)
{
    const double L = o.linkLength, m = o.linkMass, r = L / 10;
    const double across = m * (L * L / 12 + r * r / 4), along = m * r * r / 2;
    // links below each joint (itself included) and the longest chain below it
    std::vector<long> below(static_cast<std::size_t>(n) + 1, 1), height(static_cast<std::size_t>(n) + 1, 1);
    for (int k = n; k >= 2; --k) {
        below[parent[k]] += below[k];
        height[parent[k]] = std::max(height[parent[k]], height[k] + 1);
    }
    std::string t;
    t.reserve(static_cast<std::size_t>(n) * 160 + 200);
    t += "// " + title + " (bench/generate.cpp)\n";
    t += "GRAVITY 0 0 -9.81\n";
    const std::string body = " " + num(m) + " " + num(across) + " " + num(across) + " " + num(along) + "\n";
    for (int k = 1; k <= n; ++k) t += "B " + std::to_string(k) + body;
    auto limits = [](double l) { return l > 0 ? " LL " + num(-l) + " UL " + num(l) : std::string(); };
    for (int k = 1; k <= n; ++k) {
        const std::string id = std::to_string(k);
        const bool driven = o.driveEvery > 0 && (k - 1) % o.driveEvery == 0;
        const std::string axis = depth[k] % 2 == 0 ? " 1 0 0" : " 0 1 0";
        const double x = side[k] * L;
        const std::string z1 = parent[k] == 0 ? "0" : num(-L / 2);
        t += "C " + id + limits(driven ? o.driveLimit : o.limit) + "\n";
        t += "B1 " + std::to_string(parent[k]) + " P1 " + num(x) + " 0 " + z1 + " A1" + axis + " R1 0 0 1\n";
        t += "B2 " + id + " P2 0 0 " + num(L / 2) + " A2" + axis + " R2 0 0 1\n";
        if (driven) {
            const double fmax = m * 9.81 * L * static_cast<double>(below[k]) * static_cast<double>(height[k]);
            t += "D " + id + " HYD VMAX " + num(o.driveSpeed) + " FMAX " + num(fmax) + "\n";
        }
    }
    return t;
}

void checkSize(int n)
{
    if (n < 1) throw std::invalid_argument("a generated model needs at least one link");
}

}  // namespace

std::string chainModelText(int n, const GeneratedModelOptions& options)
{
    checkSize(n);
    std::vector<int> parent(static_cast<std::size_t>(n) + 1, 0), depth(parent.size(), 0);
    std::vector<double> side(parent.size(), 0.0);
    for (int k = 1; k <= n; ++k) {
        parent[k] = k - 1;
        depth[k] = k - 1;
    }
    return linksText("chain of " + std::to_string(n) + " links", n, parent, depth, side, options);
}

std::string treeModelText(int n, const GeneratedModelOptions& options)
{
    checkSize(n);
    std::vector<int> parent(static_cast<std::size_t>(n) + 1, 0), depth(parent.size(), 0);
    std::vector<double> side(parent.size(), 0.0);
    for (int k = 2; k <= n; ++k) {
        parent[k] = k / 2;
        depth[k] = depth[k / 2] + 1;
        side[k] = k % 2 == 0 ? 0.5 : -0.5;
    }
    return linksText("binary tree of " + std::to_string(n) + " links", n, parent, depth, side, options);
}

}  // namespace bench
