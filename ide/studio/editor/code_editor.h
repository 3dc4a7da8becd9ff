#pragma once
// CodeEditor: the text editor of `.pad` models. A QPlainTextEdit with
//  - a line-number gutter, with a red/amber dot on lines that have diagnostics;
//  - syntax highlighting (ModelHighlighter) of the document it shows;
//  - diagnostics as wavy underlines of the token at their line:column (red errors,
//    amber warnings, blue notes), the message and hint as a tooltip on hover;
//  - keyword completion (QCompleter, case-insensitive): Ctrl+Space, or by itself
//    after two letters of a word (not in comments, strings or numbers);
//  - goToLine(line, column), 1-based, columns in characters as the solver counts.
// The underlines follow edits (they are QTextCursor selections) until the next
// setDiagnostics() replaces them.

#include "solver/core/diagnostic.h"

#include <QList>
#include <QPlainTextEdit>
#include <QTextCursor>

#include <vector>

class QCompleter;

namespace studio {

class ModelHighlighter;

class CodeEditor : public QPlainTextEdit {
    Q_OBJECT
public:
    explicit CodeEditor(QWidget* parent = nullptr);
    ~CodeEditor() override;

    /// Shows `diagnostics` (positions in the current text) as underlines; the
    /// previous ones go. Diagnostics without a position only mark nothing.
    void setDiagnostics(const std::vector<solver::Diagnostic>& diagnostics);
    void clearDiagnostics();
    /// The diagnostics shown (as last given).
    const std::vector<solver::Diagnostic>& diagnostics() const { return m_diagnostics; }

    /// The underline selections (one per shown diagnostic), for tests and tools.
    QList<QTextEdit::ExtraSelection> diagnosticSelections() const;
    /// Tooltip (rich text) of the diagnostics whose underline covers document
    /// position `position`; empty when none does.
    QString diagnosticToolTipAt(int position) const;

    /// Moves the cursor to `line`:`column` (1-based; column in characters), scrolls
    /// it into view and takes the focus. Out-of-range values are clamped.
    void goToLine(int line, int column = 1);
    /// Line and column (1-based, characters) of the text cursor.
    int cursorLine() const;
    int cursorColumn() const;
    /// Document position of `line`:`column` (1-based, clamped).
    int positionOf(int line, int column) const;

    /// Keyword completion: the completer, and showing its popup for the word at the
    /// cursor (what Ctrl+Space does). Returns false when nothing matches.
    QCompleter* completer() const { return m_completer; }
    bool showCompletions();
    /// The part of the word before the cursor that completion would extend ("" in
    /// a comment, a string or a number).
    QString completionPrefix() const;

    /// The highlighter of the document shown. QPlainTextEdit::setDocument() is not
    /// virtual: call refreshHighlighter() after it to highlight the new document.
    ModelHighlighter* highlighter() const { return m_highlighter; }
    void refreshHighlighter();

    /// Width of the line-number gutter [px].
    int gutterWidth() const;

protected:
    void resizeEvent(QResizeEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    bool viewportEvent(QEvent* event) override;

private:
    friend class LineNumberArea;
    struct Mark {  // one per underline: m_selections[i] is mark i's range
        solver::Severity severity;
        std::size_t diagnostic;  // in m_diagnostics (its tooltip is made when shown: in the current language)
    };

    void paintGutter(QPaintEvent* event);
    bool gutterToolTip(const QPoint& pos, QString& text) const;
    void updateGutterWidth();
    void updateGutter(const QRect& rect, int dy);
    void updateExtraSelections();
    void insertCompletion(const QString& completion);
    QTextCursor tokenCursor(int line, int column) const;

    QWidget* m_gutter = nullptr;
    ModelHighlighter* m_highlighter = nullptr;
    QCompleter* m_completer = nullptr;
    std::vector<solver::Diagnostic> m_diagnostics;
    QList<Mark> m_marks;
    QList<QTextEdit::ExtraSelection> m_selections;  // the marks' underlines (cursors follow edits)
};

}  // namespace studio
