#include "ide/studio/editor/model_syntax.h"

#include "solver/parse/keywords.h"
#include "solver/parse/lexer.h"

#include <QSet>

#include <algorithm>

namespace studio {

namespace {

bool isBlank(QChar c)
{
    return c == u' ' || c == u'\t' || c == u'\r' || c == u'\v' || c == u'\f';
}

bool isControl(QChar c)
{
    const char16_t u = c.unicode();
    return (u < 0x20 && !isBlank(c)) || u == 0x7F;
}

bool startsComment(QStringView line, int i)
{
    return line[i] == u'#' || (line[i] == u'/' && i + 1 < line.size() && line[i + 1] == u'/');
}

bool isNumberWord(QStringView word)
{
    // numbers are ASCII; anything else is a word (the parser says why)
    for (QChar c : word) {
        if (c.unicode() > 0x7F) return false;
    }
    return solver::parse::looksLikeNumber(word.toLatin1().toStdString());
}

QSet<QString> toSet(const QStringList& list) { return QSet<QString>(list.begin(), list.end()); }

}  // namespace

QList<SyntaxToken> scanModelLine(QStringView line)
{
    QList<SyntaxToken> tokens;
    const int n = int(line.size());
    int i = 0;
    while (i < n) {
        const QChar c = line[i];
        if (isBlank(c) || isControl(c)) {
            ++i;
            continue;
        }
        if (startsComment(line, i)) {
            tokens.append({SyntaxToken::Kind::Comment, i, n - i});
            break;
        }
        if (c == u'"') {
            const int start = i++;
            while (i < n) {
                if (line[i] == u'\\' && i + 1 < n && (line[i + 1] == u'"' || line[i + 1] == u'\\')) {
                    i += 2;
                    continue;
                }
                if (line[i++] == u'"') break;
            }
            tokens.append({SyntaxToken::Kind::String, start, i - start});
            continue;
        }
        // a word or number runs to a blank, a quote, a control character or a comment
        const int start = i;
        while (i < n && !isBlank(line[i]) && !isControl(line[i]) && line[i] != u'"' && !startsComment(line, i)) ++i;
        const QStringView word = line.mid(start, i - start);
        tokens.append({isNumberWord(word) ? SyntaxToken::Kind::Number : SyntaxToken::Kind::Word, start, i - start});
    }
    return tokens;
}

int tokenIndexAt(const QList<SyntaxToken>& tokens, int offset)
{
    for (int k = 0; k < tokens.size(); ++k) {
        if (offset >= tokens[k].start && offset < tokens[k].end()) return k;
    }
    return -1;
}

const QStringList& statementKeywords()
{
    static const QStringList list = [] {
        QStringList words;
        for (const char* k : solver::keywords::kStatements) words.append(QString::fromLatin1(k));
        return words;
    }();
    return list;
}

const QStringList& modelKeywords()
{
    // the language's own list (solver/parse/keywords.h): statements, then every option
    static const QStringList list = [] {
        QStringList words = statementKeywords();
        for (const char* o : solver::keywords::kOptions) words.append(QString::fromLatin1(o));
        words.removeDuplicates();
        std::sort(words.begin(), words.end());
        return words;
    }();
    return list;
}

bool isModelKeyword(QStringView word)
{
    static const QSet<QString> set = toSet(modelKeywords());
    return !word.isEmpty() && set.contains(word.toString().toUpper());
}

bool isStatementKeyword(QStringView word)
{
    static const QSet<QString> set = toSet(statementKeywords());
    return !word.isEmpty() && set.contains(word.toString().toUpper());
}

int offsetOfColumn(QStringView line, int column)
{
    int i = 0;
    for (int col = 1; col < column && i < line.size(); ++col) {
        i += (line[i].isHighSurrogate() && i + 1 < line.size() && line[i + 1].isLowSurrogate()) ? 2 : 1;
    }
    return i;
}

int columnOfOffset(QStringView line, int offset)
{
    int col = 1;
    for (int i = 0; i < offset && i < line.size(); ++col) {
        i += (line[i].isHighSurrogate() && i + 1 < line.size() && line[i + 1].isLowSurrogate()) ? 2 : 1;
    }
    return col;
}

}  // namespace studio
