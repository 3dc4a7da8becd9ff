#pragma once
// ModelHighlighter: syntax colouring of `.pad` text (docs/model-language.md).
// Statement keywords (the first word of a line: B, C, G, GRAVITY …), option
// keywords (QI, NAME, BOX …, case-insensitive), numbers, ids (the number after a
// statement keyword B/C/D/F/G/B1/B2, and a body or joint reference: `B 1` in a G
// or F statement, `JOINT 2`, `TABLE Q 3`), strings and comments (`//`, `#`).
// One line at a time: the language has no multi-line constructs.

#include <QSyntaxHighlighter>
#include <QTextCharFormat>

namespace studio {

class ModelHighlighter : public QSyntaxHighlighter {
    Q_OBJECT
public:
    enum class Role { StatementKeyword, OptionKeyword, Number, Id, String, Comment };

    explicit ModelHighlighter(QTextDocument* document);

    /// The format used for `role` (tests compare these with the block layouts).
    QTextCharFormat format(Role role) const;

protected:
    void highlightBlock(const QString& text) override;

private:
    QTextCharFormat m_formats[6];
};

}  // namespace studio
