#include "ide/studio/editor/model_highlighter.h"

#include "ide/studio/editor/model_syntax.h"

#include <QColor>
#include <QFont>

namespace studio {

namespace {

QTextCharFormat makeFormat(const QColor& color, bool bold = false, bool italic = false)
{
    QTextCharFormat f;
    f.setForeground(color);
    if (bold) f.setFontWeight(QFont::Bold);
    if (italic) f.setFontItalic(true);
    return f;
}

int index(ModelHighlighter::Role r) { return static_cast<int>(r); }

}  // namespace

ModelHighlighter::ModelHighlighter(QTextDocument* document) : QSyntaxHighlighter(document)
{
    m_formats[index(Role::StatementKeyword)] = makeFormat(QColor(0x1f, 0x3f, 0xa0), true);
    m_formats[index(Role::OptionKeyword)] = makeFormat(QColor(0x00, 0x70, 0x88));
    m_formats[index(Role::Number)] = makeFormat(QColor(0xa8, 0x50, 0x00));
    m_formats[index(Role::Id)] = makeFormat(QColor(0x8a, 0x1c, 0x8a), true);
    m_formats[index(Role::String)] = makeFormat(QColor(0x2e, 0x7d, 0x32));
    m_formats[index(Role::Comment)] = makeFormat(QColor(0x80, 0x80, 0x80), false, true);
}

QTextCharFormat ModelHighlighter::format(Role role) const { return m_formats[index(role)]; }

void ModelHighlighter::highlightBlock(const QString& text)
{
    const QList<SyntaxToken> tokens = scanModelLine(text);
    bool nextNumberIsId = false;
    bool afterTable = false;
    for (int k = 0; k < tokens.size(); ++k) {
        const SyntaxToken& t = tokens[k];
        const QStringView word = QStringView(text).mid(t.start, t.length);
        switch (t.kind) {
        case SyntaxToken::Kind::Comment: setFormat(t.start, t.length, m_formats[index(Role::Comment)]); break;
        case SyntaxToken::Kind::String: setFormat(t.start, t.length, m_formats[index(Role::String)]); break;
        case SyntaxToken::Kind::Number:
            setFormat(t.start, t.length, m_formats[index(nextNumberIsId ? Role::Id : Role::Number)]);
            break;
        case SyntaxToken::Kind::Word:
            if (k == 0 && isStatementKeyword(word)) {
                setFormat(t.start, t.length, m_formats[index(Role::StatementKeyword)]);
            } else if (isModelKeyword(word)) {
                setFormat(t.start, t.length, m_formats[index(Role::OptionKeyword)]);
            }
            break;
        }
        // an id follows the statement keywords B C D F G B1 B2; a body or joint
        // reference follows B, B1, B2 (graphics, forces), JOINT and TABLE Q. (C, D, F
        // elsewhere are values: a spring's damping, a pneumatic force.)
        const QString upper = t.kind == SyntaxToken::Kind::Word ? word.toString().toUpper() : QString();
        nextNumberIsId = t.kind == SyntaxToken::Kind::Word &&
                         ((k == 0 && (upper == u"C" || upper == u"D" || upper == u"F" || upper == u"G")) ||
                          upper == u"B" || upper == u"B1" || upper == u"B2" || upper == u"JOINT" ||
                          (afterTable && upper == u"Q"));
        afterTable = upper == u"TABLE";
    }
}

}  // namespace studio
