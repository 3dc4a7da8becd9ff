#pragma once
// Diagnostics: what the model layer tells a modeler about a model file.
//
// Every diagnostic has a stable code (used by tests), a severity, a position (file,
// line, column; 1-based, columns counted in characters, i.e. Unicode code points), a
// message that says what is wrong and, where one exists, a hint that says how to fix
// it. Message and hint are kept twice: as English text (`message`, `hint`, what tests
// and logs read) and as translatable Text (an English template with %1…%9 and its
// arguments), which the front ends translate into the operator's language
// (ide/i18n/diagnostic_text.h). The solver stays Qt-free: lupdate finds the templates
// because every one is written as trText("Context", "template") (ide/CMakeLists.txt
// makes lupdate read trText as QCoreApplication::translate).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace solver {

/// A translatable text: a context and an English template with %1…%9, and its
/// arguments, each a plain value (a name, a number as written) or a Text of its own
/// (a phrase that is translated too). Built with trText(…).arg(…).
/// `value` with control characters escaped (\t, \r, \xNN; a line break kept): how a
/// value from a file or the command line is shown in a message.
std::string escapeControls(std::string_view value);

class Text {
public:
    Text() = default;
    /// `context` and `tmpl` must be string literals (they are kept as pointers).
    Text(const char* context, const char* tmpl) : m_context(context), m_tmpl(tmpl) {}

    /// Fills the lowest unused %N with a plain value (not translated).
    Text& arg(std::string value);
    Text& arg(const char* value) { return arg(std::string(value)); }
    Text& arg(long long value) { return arg(std::to_string(value)); }
    Text& arg(int value) { return arg(std::to_string(value)); }
    Text& arg(std::size_t value) { return arg(std::to_string(value)); }
    /// Fills the lowest unused %N with a phrase that is translated too.
    Text& arg(Text phrase);
    Text&& with(std::string value) && { arg(std::move(value)); return std::move(*this); }
    Text&& with(Text phrase) && { arg(std::move(phrase)); return std::move(*this); }

    bool empty() const { return m_tmpl == nullptr && m_value.empty(); }
    const char* context() const { return m_context; }
    /// The template; nullptr for a plain value.
    const char* tmpl() const { return m_tmpl; }
    /// A plain value's text.
    const std::string& value() const { return m_value; }
    const std::vector<Text>& args() const { return m_args; }

    /// The text in English (the template filled with the English arguments).
    std::string english() const;
    /// The text in another language: `translate(context, tmpl)` gives each template's
    /// translation (UTF-8), which is filled with the arguments (translated alike).
    template <class Translate>
    std::string render(const Translate& translate) const
    {
        if (!m_tmpl) return m_value;
        std::vector<std::string> filled;
        filled.reserve(m_args.size());
        for (const Text& a : m_args) filled.push_back(a.render(translate));
        return fill(translate(m_context, m_tmpl), filled);
    }
    /// Replaces %1…%9 in `tmpl` by `args` in one pass ("%%" stays; a missing argument
    /// leaves its %N as written).
    static std::string fill(const std::string& tmpl, const std::vector<std::string>& args);

private:
    friend Text plainText(std::string value);
    const char* m_context = nullptr;
    const char* m_tmpl = nullptr;
    std::string m_value;
    std::vector<Text> m_args;
};

/// A translatable text in `context` (a string literal; lupdate reads the call).
inline Text trText(const char* context, const char* tmpl) { return Text(context, tmpl); }
/// A plain value as a Text (shown as it is, in every language).
Text plainText(std::string value);

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
    std::string message;  ///< what is wrong, in English
    std::string hint;     ///< how to fix it, in English; may be empty
    Text messageText;     ///< the message, translatable (empty for an old-style English-only one)
    Text hintText;        ///< the hint, translatable

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

    /// A problem with a translatable message and hint (the English ones are derived).
    Diagnostic& error(std::string code, SourcePos pos, Text message, Text hint = {});
    Diagnostic& warning(std::string code, SourcePos pos, Text message, Text hint = {});
    Diagnostic& add(Severity s, std::string code, SourcePos pos, Text message, Text hint = {});

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
    // stores one (English only; the Text overload adds the translatable texts)
    Diagnostic& add(Severity s, std::string code, SourcePos pos, std::string message, std::string hint);

    std::string m_file;
    std::size_t m_limit;
    std::vector<Diagnostic> m_items;
    std::size_t m_errors = 0;
    std::size_t m_warnings = 0;
    std::size_t m_dropped = 0;
    Diagnostic m_sink;  // returned for dropped diagnostics
};

}  // namespace solver
