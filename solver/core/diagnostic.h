#pragma once
// Diagnostics: what the model layer tells a modeler about a model file.
//
// Every diagnostic has a stable code (used by tests and, in the GUI, by the
// translation of its text), a severity, a position (file, line, column; 1-based,
// columns counted in characters, i.e. Unicode code points), an English message
// that says what is wrong and, where one exists, a hint that says how to fix it.

#include <cstddef>
#include <string>
#include <vector>

namespace solver {

enum class Severity { Error, Warning, Note };

const char* severityName(Severity s);  ///< "error", "warning", "note"

/// A position in a source file. line/column are 1-based; 0 means "unknown".
struct SourcePos {
    int line = 0;
    int column = 0;
    bool valid() const { return line > 0; }
    friend bool operator==(const SourcePos&, const SourcePos&) = default;
};

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string code;     ///< stable identifier, kebab-case, e.g. "decimal-comma"
    std::string file;     ///< file name as given by the caller
    SourcePos pos;
    std::string message;  ///< what is wrong (English; the GUI translates by code)
    std::string hint;     ///< how to fix it; may be empty
    std::vector<std::string> args;  ///< the message's variable parts, for translation

    /// "file:line:col: error: message [hint]" — the format compilers use.
    std::string format() const;
};

/// An ordered collection of diagnostics. All problems are collected, never only
/// the first; after `limit()` errors one "too-many-errors" note is added and the
/// rest are counted but not stored (a 50 MB junk file must not eat the memory).
class Diagnostics {
public:
    static constexpr std::size_t kDefaultLimit = 10000;

    explicit Diagnostics(std::string file = {}, std::size_t limit = kDefaultLimit)
        : m_file(std::move(file)), m_limit(limit) {}

    const std::string& file() const { return m_file; }
    void setFile(std::string f) { m_file = std::move(f); }

    Diagnostic& error(std::string code, SourcePos pos, std::string message, std::string hint = {});
    Diagnostic& warning(std::string code, SourcePos pos, std::string message, std::string hint = {});
    Diagnostic& add(Severity s, std::string code, SourcePos pos, std::string message,
                    std::string hint = {});

    bool hasErrors() const { return m_errors > 0; }
    std::size_t errorCount() const { return m_errors; }
    std::size_t warningCount() const { return m_warnings; }
    bool truncated() const { return m_dropped > 0; }

    const std::vector<Diagnostic>& items() const { return m_items; }
    auto begin() const { return m_items.begin(); }
    auto end() const { return m_items.end(); }
    std::size_t size() const { return m_items.size(); }
    bool empty() const { return m_items.empty(); }

    /// Sorts by position (stable), so the listing reads top to bottom.
    void sortByPosition();
    /// Appends another list's items (keeping their file names).
    void append(const Diagnostics& other);

private:
    std::string m_file;
    std::size_t m_limit;
    std::vector<Diagnostic> m_items;
    std::size_t m_errors = 0;
    std::size_t m_warnings = 0;
    std::size_t m_dropped = 0;
    Diagnostic m_sink;  // returned for dropped diagnostics
};

}  // namespace solver
