#include "ide/studio/editor/code_editor.h"

#include "ide/studio/editor/diagnostic_text.h"
#include "ide/studio/editor/model_highlighter.h"
#include "ide/studio/editor/model_syntax.h"

#include <QAbstractItemView>
#include <QCompleter>
#include <QFontDatabase>
#include <QHash>
#include <QHelpEvent>
#include <QKeyEvent>
#include <QPainter>
#include <QScrollBar>
#include <QStringListModel>
#include <QTextBlock>
#include <QToolTip>

#include <algorithm>

namespace studio {

namespace {

/// Most underlines drawn (a junk file can have 10,000 diagnostics; the problems list
/// shows them all). Each is a live QTextCursor that every edit updates.
constexpr int kMaxMarks = 1000;

int rank(solver::Severity s)
{
    switch (s) {
    case solver::Severity::Error: return 3;
    case solver::Severity::Warning: return 2;
    case solver::Severity::Note: return 1;
    }
    return 0;
}

}  // namespace

/// The gutter: paints through its editor.
class LineNumberArea : public QWidget {
public:
    explicit LineNumberArea(CodeEditor* editor) : QWidget(editor), m_editor(editor) {}
    QSize sizeHint() const override { return {m_editor->gutterWidth(), 0}; }

protected:
    void paintEvent(QPaintEvent* event) override { m_editor->paintGutter(event); }
    bool event(QEvent* event) override
    {
        if (event->type() == QEvent::ToolTip) {
            auto* help = static_cast<QHelpEvent*>(event);
            QString text;
            if (m_editor->gutterToolTip(help->pos(), text)) {
                QToolTip::showText(help->globalPos(), text, this);
            } else {
                QToolTip::hideText();
                event->ignore();
            }
            return true;
        }
        return QWidget::event(event);
    }

private:
    CodeEditor* m_editor;
};

CodeEditor::CodeEditor(QWidget* parent) : QPlainTextEdit(parent)
{
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setLineWrapMode(QPlainTextEdit::NoWrap);
    setTabStopDistance(4 * fontMetrics().horizontalAdvance(QLatin1Char(' ')));
    setMouseTracking(true);

    m_gutter = new LineNumberArea(this);
    connect(this, &QPlainTextEdit::blockCountChanged, this, &CodeEditor::updateGutterWidth);
    connect(this, &QPlainTextEdit::updateRequest, this, &CodeEditor::updateGutter);
    connect(this, &QPlainTextEdit::cursorPositionChanged, this, &CodeEditor::updateExtraSelections);
    updateGutterWidth();

    m_highlighter = new ModelHighlighter(document());

    auto* model = new QStringListModel(modelKeywords(), this);
    m_completer = new QCompleter(model, this);
    m_completer->setWidget(this);
    m_completer->setCompletionMode(QCompleter::PopupCompletion);
    m_completer->setCaseSensitivity(Qt::CaseInsensitive);
    m_completer->setModelSorting(QCompleter::CaseInsensitivelySortedModel);
    m_completer->setWrapAround(false);
    connect(m_completer, qOverload<const QString&>(&QCompleter::activated), this, &CodeEditor::insertCompletion);

    updateExtraSelections();
}

CodeEditor::~CodeEditor() = default;

void CodeEditor::refreshHighlighter()
{
    if (m_highlighter->document() != document()) m_highlighter->setDocument(document());
}

// ---- gutter ----------------------------------------------------------------

int CodeEditor::gutterWidth() const
{
    int digits = 1;
    for (int max = std::max(1, blockCount()); max >= 10; max /= 10) ++digits;
    const int charWidth = fontMetrics().horizontalAdvance(QLatin1Char('9'));
    // a dot for the diagnostics, the numbers, a little space
    return fontMetrics().height() / 2 + 6 + charWidth * std::max(digits, 2) + 8;
}

void CodeEditor::updateGutterWidth() { setViewportMargins(gutterWidth(), 0, 0, 0); }

void CodeEditor::updateGutter(const QRect& rect, int dy)
{
    if (dy) {
        m_gutter->scroll(0, dy);
    } else {
        m_gutter->update(0, rect.y(), m_gutter->width(), rect.height());
    }
    if (rect.contains(viewport()->rect())) updateGutterWidth();
}

void CodeEditor::resizeEvent(QResizeEvent* event)
{
    QPlainTextEdit::resizeEvent(event);
    const QRect cr = contentsRect();
    m_gutter->setGeometry(QRect(cr.left(), cr.top(), gutterWidth(), cr.height()));
}

void CodeEditor::paintGutter(QPaintEvent* event)
{
    QPainter painter(m_gutter);
    const QPalette pal = palette();
    painter.fillRect(event->rect(), pal.color(QPalette::Window));

    // the worst severity per line
    QHash<int, solver::Severity> lineSeverity;
    for (int i = 0; i < m_marks.size(); ++i) {
        const int block = m_selections[i].cursor.block().blockNumber();
        auto it = lineSeverity.find(block);
        if (it == lineSeverity.end() || rank(m_marks[i].severity) > rank(*it)) lineSeverity[block] = m_marks[i].severity;
    }

    const int current = textCursor().blockNumber();
    const int dot = fontMetrics().height() / 2;
    QTextBlock block = firstVisibleBlock();
    int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
    int bottom = top + qRound(blockBoundingRect(block).height());
    while (block.isValid() && top <= event->rect().bottom()) {
        if (block.isVisible() && bottom >= event->rect().top()) {
            const int n = block.blockNumber();
            auto it = lineSeverity.constFind(n);
            if (it != lineSeverity.constEnd()) {
                painter.setRenderHint(QPainter::Antialiasing);
                painter.setPen(Qt::NoPen);
                painter.setBrush(severityColor(*it));
                painter.drawEllipse(QRect(3, top + (fontMetrics().height() - dot) / 2, dot, dot));
            }
            QFont f = font();
            f.setBold(n == current);
            painter.setFont(f);
            painter.setPen(n == current ? pal.color(QPalette::WindowText) : pal.color(QPalette::PlaceholderText));
            painter.drawText(0, top, m_gutter->width() - 6, fontMetrics().height(), Qt::AlignRight,
                             QString::number(n + 1));
        }
        block = block.next();
        top = bottom;
        bottom = top + qRound(blockBoundingRect(block).height());
    }
}

bool CodeEditor::gutterToolTip(const QPoint& pos, QString& text) const
{
    const QTextCursor at = cursorForPosition(QPoint(0, pos.y()));
    const int block = at.blockNumber();
    QStringList tips;
    for (int i = 0; i < m_marks.size(); ++i) {
        if (m_selections[i].cursor.block().blockNumber() == block) tips << diagnosticToolTip(m_diagnostics[m_marks[i].diagnostic]);
    }
    tips.removeDuplicates();
    text = tips.join(QString());
    return !tips.isEmpty();
}

// ---- diagnostics ------------------------------------------------------------

QTextCursor CodeEditor::tokenCursor(int line, int column) const
{
    QTextBlock block = document()->findBlockByNumber(line - 1);
    if (!block.isValid()) return {};
    const QString text = block.text();
    const QList<SyntaxToken> tokens = scanModelLine(text);
    const int offset = offsetOfColumn(text, std::max(column, 1));
    int from = offset, to = offset;
    int k = tokenIndexAt(tokens, offset);
    if (k < 0 && !tokens.isEmpty() && offset >= tokens.last().start) k = int(tokens.size()) - 1;  // past the end: the last token
    if (k >= 0) {
        const SyntaxToken& t = tokens[k];
        if (t.kind == SyntaxToken::Kind::Comment) {
            to = std::min(int(text.size()), offset + 1);
        } else {
            from = t.start;  // the whole token
            to = t.end();
        }
    } else if (offset < text.size()) {
        to = offset + 1;  // a blank or a control character
    }
    QTextCursor c(block);
    c.setPosition(block.position() + from);
    c.setPosition(block.position() + to, QTextCursor::KeepAnchor);
    return c;
}

void CodeEditor::setDiagnostics(const std::vector<solver::Diagnostic>& diagnostics)
{
    m_diagnostics = diagnostics;
    m_marks.clear();
    m_selections.clear();
    // the most severe first when there are too many; then drawn warnings first,
    // errors last, so that errors lie over warnings
    std::vector<const solver::Diagnostic*> order;
    for (const solver::Diagnostic& d : m_diagnostics) {
        if (d.pos.valid()) order.push_back(&d);
    }
    auto bySeverity = [](const solver::Diagnostic* a, const solver::Diagnostic* b) { return rank(a->severity) > rank(b->severity); };
    std::stable_sort(order.begin(), order.end(), bySeverity);
    if (order.size() > std::size_t(kMaxMarks)) order.resize(kMaxMarks);
    std::reverse(order.begin(), order.end());
    for (const solver::Diagnostic* d : order) {
        QTextCursor c = tokenCursor(d->pos.line, d->pos.column);
        if (c.isNull()) continue;
        // one live cursor per mark, in its selection: it follows edits
        QTextEdit::ExtraSelection sel;
        sel.cursor = c;
        sel.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
        sel.format.setUnderlineColor(severityColor(d->severity));
        m_selections.append(sel);
        m_marks.append({d->severity, std::size_t(d - m_diagnostics.data())});
    }
    updateExtraSelections();
    m_gutter->update();
}

void CodeEditor::clearDiagnostics() { setDiagnostics({}); }

QList<QTextEdit::ExtraSelection> CodeEditor::diagnosticSelections() const { return m_selections; }

QString CodeEditor::diagnosticToolTipAt(int position) const
{
    QStringList tips;
    for (int i = 0; i < m_marks.size(); ++i) {
        const QTextCursor& c = m_selections[i].cursor;
        const int a = c.selectionStart(), b = c.selectionEnd();
        if (position >= a && (position < b || (a == b && position == a))) tips << diagnosticToolTip(m_diagnostics[m_marks[i].diagnostic]);
    }
    tips.removeDuplicates();
    return tips.join(QString());
}

void CodeEditor::updateExtraSelections()
{
    QList<QTextEdit::ExtraSelection> all;
    if (!isReadOnly()) {
        QTextEdit::ExtraSelection line;
        QColor tint = palette().color(QPalette::Highlight);
        tint.setAlpha(28);
        line.format.setBackground(tint);
        line.format.setProperty(QTextFormat::FullWidthSelection, true);
        line.cursor = textCursor();
        line.cursor.clearSelection();
        all.append(line);
    }
    all.append(m_selections);
    setExtraSelections(all);
}

bool CodeEditor::viewportEvent(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        const QTextCursor at = cursorForPosition(help->pos());
        // the character under the mouse: cursorForPosition rounds to the nearest gap
        int position = at.position();
        const QRect r = cursorRect(at);
        if (help->pos().x() < r.left() && position > at.block().position()) --position;
        // past the end of the line there is nothing to explain
        QTextCursor lineEnd(at.block());
        lineEnd.movePosition(QTextCursor::EndOfBlock);
        const bool pastEnd = help->pos().x() > cursorRect(lineEnd).right() + fontMetrics().horizontalAdvance(QLatin1Char(' '));
        const QString tip = pastEnd ? QString() : diagnosticToolTipAt(position);
        if (tip.isEmpty()) {
            QToolTip::hideText();
        } else {
            QToolTip::showText(help->globalPos(), tip, viewport());
        }
        return true;
    }
    return QPlainTextEdit::viewportEvent(event);
}

// ---- navigation ---------------------------------------------------------------

int CodeEditor::positionOf(int line, int column) const
{
    const int n = std::clamp(line, 1, std::max(1, blockCount()));
    const QTextBlock block = document()->findBlockByNumber(n - 1);
    return block.position() + offsetOfColumn(block.text(), std::max(column, 1));
}

void CodeEditor::goToLine(int line, int column)
{
    QTextCursor c = textCursor();
    c.setPosition(positionOf(line, column));
    setTextCursor(c);
    centerCursor();
    setFocus(Qt::OtherFocusReason);
}

int CodeEditor::cursorLine() const { return textCursor().blockNumber() + 1; }

int CodeEditor::cursorColumn() const
{
    const QTextCursor c = textCursor();
    return columnOfOffset(c.block().text(), c.positionInBlock());
}

// ---- completion -----------------------------------------------------------------

QString CodeEditor::completionPrefix() const
{
    const QTextCursor c = textCursor();
    const QString text = c.block().text();
    const int at = c.positionInBlock();
    const QList<SyntaxToken> tokens = scanModelLine(text);
    for (const SyntaxToken& t : tokens) {
        if (t.kind == SyntaxToken::Kind::Comment && at > t.start) return {};
        if (at > t.start && at <= t.end()) {
            if (t.kind != SyntaxToken::Kind::Word) return {};
            const QString prefix = text.mid(t.start, at - t.start);
            // keywords are letters and digits, starting with a letter
            if (!prefix.front().isLetter()) return {};
            for (QChar ch : prefix) {
                if (!ch.isLetterOrNumber()) return {};
            }
            return prefix;
        }
    }
    return {};
}

bool CodeEditor::showCompletions()
{
    const QString prefix = completionPrefix();
    // in a comment or string nothing is offered; elsewhere an empty prefix offers all
    const QTextCursor c = textCursor();
    const QList<SyntaxToken> tokens = scanModelLine(c.block().text());
    for (const SyntaxToken& t : tokens) {
        if (c.positionInBlock() > t.start && c.positionInBlock() <= t.end() && prefix.isEmpty()) {
            m_completer->popup()->hide();
            return false;
        }
    }
    m_completer->setCompletionPrefix(prefix);
    if (m_completer->completionCount() == 0) {
        m_completer->popup()->hide();
        return false;
    }
    m_completer->popup()->setCurrentIndex(m_completer->completionModel()->index(0, 0));
    QRect r = cursorRect();
    r.translate(viewport()->pos());  // cursorRect() is in viewport coordinates
    r.setWidth(m_completer->popup()->sizeHintForColumn(0) + m_completer->popup()->verticalScrollBar()->sizeHint().width() + 8);
    m_completer->complete(r);
    return true;
}

void CodeEditor::insertCompletion(const QString& completion)
{
    if (m_completer->widget() != this) return;
    const QString prefix = completionPrefix();
    QTextCursor c = textCursor();
    c.movePosition(QTextCursor::Left, QTextCursor::KeepAnchor, int(prefix.size()));
    c.insertText(completion);
    setTextCursor(c);
}

void CodeEditor::keyPressEvent(QKeyEvent* event)
{
    QAbstractItemView* popup = m_completer->popup();
    if (popup->isVisible()) {
        // the completer handles these keys
        switch (event->key()) {
        case Qt::Key_Enter:
        case Qt::Key_Return:
        case Qt::Key_Escape:
        case Qt::Key_Tab:
        case Qt::Key_Backtab: event->ignore(); return;
        default: break;
        }
    }
    const bool ctrlSpace = event->key() == Qt::Key_Space && (event->modifiers() & Qt::ControlModifier);
    if (ctrlSpace) {
        showCompletions();
        return;
    }
    QPlainTextEdit::keyPressEvent(event);

    // by itself after two letters of a word, while typing
    const QString typed = event->text();
    const bool typing = !typed.isEmpty() && typed.back().isLetterOrNumber() &&
                        !(event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier));
    const bool erasing = event->key() == Qt::Key_Backspace && popup->isVisible();
    if (!typing && !erasing) {
        popup->hide();
        return;
    }
    const QString prefix = completionPrefix();
    if (prefix.size() < 2) {
        popup->hide();
        return;
    }
    m_completer->setCompletionPrefix(prefix);
    // nothing to offer, or the word is already the one keyword it could be
    if (m_completer->completionCount() == 0 ||
        (m_completer->completionCount() == 1 && m_completer->currentCompletion().compare(prefix, Qt::CaseInsensitive) == 0)) {
        popup->hide();
        return;
    }
    showCompletions();
}

}  // namespace studio
