#pragma once
// Lexer of the model language: splits one line into tokens.
//
// Tokens are separated by blanks (space, tab). `//` and `#` start a comment to the
// end of the line. Strings are in double quotes (`\"` and `\\` escapes). A token
// that reads as a number (`12`, `-.2`, `1e-3`, `+4.5E2`) is a Number; anything
// else is a Word (keywords, and malformed numbers that the parser diagnoses).
// Columns count characters (code points), 1-based.

#include "solver/core/diagnostic.h"

#include <string>
#include <string_view>
#include <vector>

namespace solver::parse {

struct Token {
    enum class Kind { Word, Number, String };
    Kind kind = Kind::Word;
    std::string text;    ///< as written (strings: unescaped contents)
    double number = 0;   ///< Number only
    SourcePos pos;
    bool isWord() const { return kind == Kind::Word; }
    bool isNumber() const { return kind == Kind::Number; }
    bool isString() const { return kind == Kind::String; }
    /// Case-insensitive keyword comparison (`kw` must be upper case).
    bool is(std::string_view kw) const;
};

/// Why a word is not a number, for a word that looks like one; empty when it does not.
/// "decimal-comma" for `4,38325`, "not-finite" for NaN/Inf, "out-of-range" for 1e999.
std::string numberProblem(std::string_view word);

/// Tokenizes one line (without its newline). Problems (unterminated string, control
/// characters, numbers out of range) go to `diags`.
std::vector<Token> tokenizeLine(std::string_view line, int lineNo, Diagnostics& diags);
/// The same into `tokens` (cleared first), whose storage a caller that reads many
/// lines keeps from one line to the next.
void tokenizeLine(std::string_view line, int lineNo, Diagnostics& diags, std::vector<Token>& tokens);

/// True when `word` is a number of the language exactly:
/// [+-]?(d+(.d*)?|.d+)([eE][+-]?d+)? (the range is not checked).
bool looksLikeNumber(std::string_view word);

/// Upper-cases ASCII letters.
std::string upper(std::string_view s);

/// Number of code points in the first `bytes` bytes of `s` (valid UTF-8 expected).
int columnOf(std::string_view s, std::size_t bytes);

}  // namespace solver::parse
