#pragma once
// `padrob inertia MODEL [--body I] [--write]` (docs/cli.md): each body's mass, centre of
// mass and inertia tensor computed from its solids (graphics with MASS or RHO), beside the
// B line in the file; `--write` puts the computed B lines into the file.

#include <string>
#include <vector>

namespace ide::cli {

std::string inertiaHelp();
/// Runs the command; returns the exit status (0 ok, 1 model errors, 2 usage error or a
/// file that cannot be read or written).
int runInertia(const std::vector<std::string>& args);

/// The text of model file `text` with the B statement that starts at byte `offset` replaced
/// by `statement` (which must be "B id …" without NAME); the NAME "…" part, the spacing
/// before a trailing comment (the comment's column kept where it fits) and the comment are
/// kept, and every other byte. Empty when no B statement starts at `offset`.
std::string replaceBodyStatement(const std::string& text, std::size_t offset, const std::string& statement);

}  // namespace ide::cli
