// `padrob inertia`: body mass properties from their solids, compared with (or written into)
// the model's B statements.

#include "ide/cli/inertia.h"
#include "ide/cli/cli_io.h"

#include "solver/core/output_file.h"
#include "solver/inertia/solid_inertia.h"
#include "solver/pipeline.h"

#include "ide/i18n/diagnostic_text.h"
#include "ide/i18n/language.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

namespace ide::cli {

namespace {

constexpr int kOk = 0, kModelErrors = 1, kUsage = 2;

using i18n::trStd;

void print(std::FILE* f, const std::string& s) { std::fwrite(s.data(), 1, s.size(), f); }

int usage(const std::string& message)
{
    return usageError("inertia", message);
}

/// Relative difference of `computed` from `written`, as a signed percentage ("+12.50%").
std::string relative(double computed, double written)
{
    if (written == 0) return computed == 0 ? "0%" : trStd("padrob", "n/a (file: 0)");
    std::string s = fixed(100.0 * (computed - written) / std::abs(written), 2);
    return (s[0] == '-' ? s : "+" + s) + "%";
}

/// The B statement "B id m Ixx Iyy Izz Ixy Iyz Ixz CG x y z" of computed mass properties;
/// values negligible next to the body's size are written as 0 (no "-1e-17").
std::string bodyStatement(int id, const solver::MassProperties& p)
{
    const Eigen::Matrix3d& i = p.inertia;
    const double iScale = i.diagonal().cwiseAbs().maxCoeff();
    const auto moment = [&](double v) { return num(std::abs(v) <= 1e-9 * iScale ? 0.0 : v); };
    const double cScale = std::max(1.0, p.com.cwiseAbs().maxCoeff());
    const auto length = [&](double v) { return num(std::abs(v) <= 1e-12 * cScale ? 0.0 : v); };
    return "B " + std::to_string(id) + " " + num(p.mass) + " " + moment(i(0, 0)) + " " + moment(i(1, 1)) + " " +
           moment(i(2, 2)) + " " + moment(i(0, 1)) + " " + moment(i(1, 2)) + " " + moment(i(0, 2)) + " CG " +
           length(p.com.x()) + " " + length(p.com.y()) + " " + length(p.com.z());
}

/// Characters (UTF-8 code points) in text[b, e).
std::size_t codePoints(const std::string& text, std::size_t b, std::size_t e)
{
    std::size_t n = 0;
    for (std::size_t k = b; k < e; ++k) n += (static_cast<unsigned char>(text[k]) & 0xC0) != 0x80;
    return n;
}

/// Byte range [begin, end) of 1-based line `line` (without its "\r\n" or "\n").
std::optional<std::pair<std::size_t, std::size_t>> lineRange(const std::string& text, int line)
{
    std::size_t b = 0;
    for (int l = 1; l < line; ++l) {
        b = text.find('\n', b);
        if (b == std::string::npos) return std::nullopt;
        ++b;
    }
    std::size_t e = text.find('\n', b);
    if (e == std::string::npos) e = text.size();
    if (e > b && text[e - 1] == '\r') --e;
    return std::make_pair(b, e);
}

/// Byte offset of 1-based column `column` (code points) in line [b, e).
std::optional<std::size_t> columnOffset(const std::string& text, std::size_t b, std::size_t e, int column)
{
    int c = 1;
    for (std::size_t k = b; k < e; ++k) {
        if ((static_cast<unsigned char>(text[k]) & 0xC0) == 0x80) continue;
        if (c == column) return k;
        ++c;
    }
    return std::nullopt;
}

bool readFile(const std::string& path, std::string& out)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    out.assign(std::istreambuf_iterator<char>(in), {});
    return !in.bad();
}

}  // namespace

std::string replaceBodyStatement(const std::string& text, std::size_t offset, const std::string& statement)
{
    std::size_t lineEnd = text.find('\n', offset);
    if (lineEnd == std::string::npos) lineEnd = text.size();
    if (lineEnd > offset && text[lineEnd - 1] == '\r') --lineEnd;
    if (offset >= lineEnd || text[offset] != 'B' || offset + 1 >= lineEnd || (text[offset + 1] != ' ' && text[offset + 1] != '\t')) {
        return {};
    }
    std::size_t lineStart = text.rfind('\n', offset);
    lineStart = lineStart == std::string::npos ? 0 : lineStart + 1;
    // the statement's tokens up to a comment (// or #) or the end of the line
    std::size_t k = offset, stmtEnd = offset;
    std::string name;  // NAME's string token as written
    bool afterName = false;
    while (k < lineEnd) {
        if (text[k] == ' ' || text[k] == '\t') {
            ++k;
            continue;
        }
        if (text[k] == '#' || text.compare(k, 2, "//") == 0) break;
        std::size_t t = k;
        if (text[k] == '"') {
            const std::size_t close = text.find('"', k + 1);
            if (close == std::string::npos || close >= lineEnd) return {};
            t = close + 1;
        } else {
            while (t < lineEnd && text[t] != ' ' && text[t] != '\t' && text[t] != '"') ++t;
        }
        const std::string token = text.substr(k, t - k);
        if (afterName) {
            if (token.empty() || token[0] != '"') return {};
            name = token;
            afterName = false;
        } else if (token == "NAME") {
            afterName = true;
        }
        stmtEnd = t;
        k = t;
    }
    if (afterName) return {};
    std::string replacement = statement + (name.empty() ? "" : " NAME " + name);
    // keep a trailing comment where it was when there is room, else two spaces before it
    std::string gap = text.substr(stmtEnd, k - stmtEnd);
    if (k < lineEnd && gap.size() >= 2 && gap.find('\t') == std::string::npos) {
        const std::size_t commentColumn = codePoints(text, lineStart, k);
        const std::size_t newEnd = codePoints(text, lineStart, offset) + codePoints(replacement, 0, replacement.size());
        gap.assign(commentColumn >= newEnd + 2 ? commentColumn - newEnd : 2, ' ');
    }
    return text.substr(0, offset) + replacement + gap + text.substr(k);
}

std::string inertiaHelp()
{
    return trStd("padrob", "Usage: padrob inertia MODEL [--body I] [--write]\n"
              "\n"
              "Computes each body's mass, centre of mass and inertia tensor (about the centre of\n"
              "mass, in body axes) from its solids: the graphics (G) with MASS or RHO, combined\n"
              "with the parallel-axis theorem. For each such body it prints the computed B line\n"
              "beside the one in the file, the relative difference of the mass and of each\n"
              "moment, and the principal moments.\n"
              "\n"
              "  --body I   only body I\n"
              "  --write    replace each computed body's B line in the file (its NAME and any\n"
              "             comment are kept, every other line byte for byte), after copying\n"
              "             the file to MODEL.bak\n"
              "\n"
              "A model with errors (or a mesh that cannot be used) is not computed and not\n"
              "written: its problems are printed as by 'padrob check' and the exit status is 1.\n"
              "Exit status 2 on a usage error or a file that cannot be read or written.\n");
}

int runInertia(const std::vector<std::string>& args)
{
    bool write = false;
    std::optional<int> onlyBody;
    std::vector<std::string> files;
    for (std::size_t k = 0; k < args.size(); ++k) {
        const std::string& a = args[k];
        if (a == "-h" || a == "--help") {
            print(stdout, inertiaHelp());
            return kOk;
        }
        if (a == "--write") write = true;
        else if (a == "--body") {
            if (k + 1 >= args.size()) return usage(trStd("padrob", "--body needs a body id"));
            const std::string& v = args[++k];
            int id = 0;
            auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), id);
            if (ec != std::errc() || p != v.data() + v.size() || id <= 0) {
                return usage(fill(trStd("padrob", "--body takes a body id (a positive integer), not '%1'"), {v}));
            }
            onlyBody = id;
        } else if (a.size() > 1 && a[0] == '-') {
            return usage(fill(trStd("padrob", "unknown option '%1'"), {a}));
        } else files.push_back(a);
    }
    if (files.empty()) return usage(trStd("padrob", "no model given"));
    if (files.size() != 1) return usage(trStd("padrob", "give one model"));
    const std::string& file = files[0];

    // load and check the model
    solver::CompiledModel m = solver::compileFile(file);
    bool io = false;
    for (const solver::Diagnostic& d : m.diagnostics) {
        printDiagnostic(stderr, d);
        io = io || d.code == "io-error";
    }
    if (io) return kUsage;
    if (!m.ok()) return kModelErrors;
    if (onlyBody && !m.spec.body(*onlyBody)) {
        return usage(fill(trStd("padrob", "--body: the model has no body %1"), {std::to_string(*onlyBody)}));
    }

    // compute every body with solids
    solver::Diagnostics diags(file);
    struct Computed {
        const solver::BodySpec* body;
        solver::MassProperties props;
    };
    std::vector<Computed> computed;
    for (const solver::BodySpec& b : m.spec.bodies) {
        if (b.id == 0 || (onlyBody && b.id != *onlyBody)) continue;
        if (auto p = solver::bodyMassProperties(m.spec, b.id, diags)) computed.push_back({&b, *p});
    }
    for (const solver::Diagnostic& d : diags) printDiagnostic(stderr, d);
    if (diags.hasErrors()) return kModelErrors;
    if (computed.empty()) {
        if (onlyBody) {
            print(stderr, "padrob inertia: " +
                              fill(trStd("padrob", "body %1 has no solids (graphics with MASS or RHO)"), {std::to_string(*onlyBody)}) +
                              "\n");
            return kModelErrors;
        }
        print(stdout, trStd("padrob", "No body has solids (graphics with MASS or RHO): nothing to compute.") + "\n");
        return kOk;
    }

    std::string text;
    if (!readFile(file, text)) {
        print(stderr, "padrob inertia: " + fill(trStd("padrob", "cannot read '%1'"), {file}) + "\n");
        return kUsage;
    }
    std::string updated = text;
    std::string out;
    // bodies from the bottom of the file up, so earlier offsets stay valid while writing
    std::vector<std::size_t> order(computed.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return computed[a].body->src.pos.line > computed[b].body->src.pos.line;
    });
    // the labels of each body's lines, their values in one column (at least where the
    // English ones put them); the difference's " m" one further
    const std::string fileLabel = trStd("padrob", "file:"), computedLabel = trStd("padrob", "computed:"),
                      differenceLabel = trStd("padrob", "difference:"), principalLabel = trStd("padrob", "principal:");
    std::size_t labelWidth = 11;
    labelWidth = std::max(labelWidth, codePoints(differenceLabel, 0, differenceLabel.size()));
    for (const std::string* l : {&fileLabel, &computedLabel, &principalLabel}) {
        labelWidth = std::max(labelWidth, codePoints(*l, 0, l->size()) + 1);
    }
    for (const Computed& c : computed) {
        const solver::BodySpec& b = *c.body;
        const solver::MassProperties& p = c.props;
        std::string fileLine;
        if (auto r = lineRange(text, b.src.pos.line)) {
            std::size_t s = r->first, e = r->second;
            while (s < e && (text[s] == ' ' || text[s] == '\t')) ++s;
            while (e > s && (text[e - 1] == ' ' || text[e - 1] == '\t')) --e;
            fileLine = text.substr(s, e - s);
        }
        const solver::PrincipalAxes pa = solver::principalAxes(p.inertia);
        out += fill(trStd("padrob", "body %1"), {std::to_string(b.id)}) + (b.name.empty() ? "" : " \"" + b.name + "\"") + "\n";
        out += "  " + pad(fileLabel, labelWidth) + fileLine + "\n";
        out += "  " + pad(computedLabel, labelWidth) + bodyStatement(b.id, p) + "\n";
        out += "  " + pad(differenceLabel, labelWidth - 1) + " m " + relative(p.mass, b.mass) + "  Ixx " +
               relative(p.inertia(0, 0), b.inertia.x()) + "  Iyy " + relative(p.inertia(1, 1), b.inertia.y()) + "  Izz " +
               relative(p.inertia(2, 2), b.inertia.z()) + "\n";
        out += "  " + pad(principalLabel, labelWidth) + num(pa.moments.x()) + " " + num(pa.moments.y()) + " " +
               num(pa.moments.z()) + " kg·m²\n";
    }
    print(stdout, out);
    if (!write) return kOk;

    // --write: replace the B statements, check the result, back up, then write
    for (std::size_t k : order) {
        const Computed& c = computed[k];
        std::optional<std::size_t> offset;
        if (auto r = lineRange(updated, c.body->src.pos.line)) offset = columnOffset(updated, r->first, r->second, c.body->src.pos.column);
        std::string next = offset ? replaceBodyStatement(updated, *offset, bodyStatement(c.body->id, c.props)) : std::string();
        if (next.empty()) {
            print(stderr, "padrob inertia: " +
                              fill(trStd("padrob", "cannot find body %1's B statement in the file; nothing written"),
                                   {std::to_string(c.body->id)}) +
                              "\n");
            return kModelErrors;
        }
        updated = std::move(next);
    }
    solver::CompiledModel check = solver::compileText(updated, file);
    bool same = check.ok() && check.spec.bodies.size() == m.spec.bodies.size() && check.spec.joints.size() == m.spec.joints.size() &&
                check.spec.graphics.size() == m.spec.graphics.size();
    for (const Computed& c : computed) {
        const solver::BodySpec* b = same ? check.spec.body(c.body->id) : nullptr;
        same = same && b && b->name == c.body->name && std::abs(b->mass - c.props.mass) <= 1e-5 * c.props.mass;
    }
    if (!same) {
        for (const solver::Diagnostic& d : check.diagnostics) printDiagnostic(stderr, d);
        print(stderr, "padrob inertia: " + trStd("padrob", "the updated model would not load as computed; nothing written") + "\n");
        return kModelErrors;
    }
    // both whole, on the disk, or not at all; the model keeps its permissions
    // (solver/core/output_file.h)
    const std::string backup = file + ".bak";
    solver::Text writeError;
    if (!solver::writeWholeFile(backup, text, {file}, writeError)) {
        print(stderr, "padrob inertia: " + fill(trStd("padrob", "cannot write the backup '%1'; nothing written"), {backup}) + "\n");
        return kUsage;
    }
    if (!solver::writeWholeFile(file, updated, {}, writeError)) {
        print(stderr, "padrob inertia: " + fill(trStd("padrob", "cannot write '%1'"), {file}) + "\n");
        return kUsage;
    }
    const int written = static_cast<int>(computed.size());
    print(stdout, fill(trStd("padrob", "Wrote %n B line(s) to %1 (the old file is %2)", nullptr, written), {file, backup}) + "\n");
    return kOk;
}

}  // namespace ide::cli
