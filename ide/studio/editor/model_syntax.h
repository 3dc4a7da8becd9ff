#pragma once
// The model language as the editor sees it: the keywords (for highlighting and
// completion) and a scanner that splits one line of text into words, numbers,
// strings and the comment, with the lexical rules of solver/parse/lexer.h
// (blanks separate tokens; `//` and `#` start a comment outside strings; strings
// in double quotes with `\"` and `\\` escapes; a word is a number exactly when
// solver::parse::looksLikeNumber says so). Offsets are QString (UTF-16) indices.

#include <QList>
#include <QString>
#include <QStringList>
#include <QStringView>

namespace studio {

struct SyntaxToken {
    enum class Kind { Word, Number, String, Comment };
    Kind kind = Kind::Word;
    int start = 0;   ///< UTF-16 offset in the line
    int length = 0;  ///< UTF-16 units (a string includes its quotes)
    int end() const { return start + length; }
};

/// Splits one line (no newline) into tokens, left to right; a comment is the last.
QList<SyntaxToken> scanModelLine(QStringView line);

/// The token containing UTF-16 offset `offset` (start <= offset < end), or -1.
int tokenIndexAt(const QList<SyntaxToken>& tokens, int offset);

/// Every keyword of the language, upper case, sorted (docs/model-language.md).
const QStringList& modelKeywords();
/// Keywords that start a statement (GRAVITY RESTITUTION B C B1 B2 CL1 CL2 D F G).
const QStringList& statementKeywords();
/// Case-insensitive: is `word` a keyword / a statement keyword?
bool isModelKeyword(QStringView word);
bool isStatementKeyword(QStringView word);

/// UTF-16 offset of 1-based column `column` (counted in characters = code points,
/// as the solver's diagnostics count them) in `line`; clamped to the line's length.
int offsetOfColumn(QStringView line, int column);
/// 1-based column (code points) of UTF-16 offset `offset` in `line`.
int columnOfOffset(QStringView line, int offset);

}  // namespace studio
