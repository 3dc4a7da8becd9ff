// GUI tests of the model editor (ide/studio/editor): highlighting, completion,
// live diagnostics (underline, tooltip, problems list, jump), Apply, files
// (save/saveAs/open, read-only folders, CRLF), the file watcher and recovery
// copies. Real widgets on an X server (Xvfb under scripts/test.sh).

#include "tests/common/as_user.h"
#include "ide/i18n/diagnostic_text.h"
#include "ide/i18n/language.h"
#include "ide/studio/editor/code_editor.h"
#include "ide/studio/editor/editor_panel.h"
#include "ide/studio/editor/model_document.h"
#include "ide/studio/editor/model_highlighter.h"
#include "ide/studio/editor/model_syntax.h"
#include "ide/studio/editor/problems_view.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QCompleter>
#include <QDir>
#include <QElapsedTimer>
#include <QTimer>
#include <QFile>
#include <QHelpEvent>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPushButton>
#include <QScreen>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextLayout>
#include <QToolTip>

#include <unistd.h>

using namespace studio;

namespace {

QString readAll(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(f.readAll());
}

QByteArray readBytes(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return f.readAll();
}

bool writeAll(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate)) return false;
    return f.write(bytes) == bytes.size();
}

QString pendulumText() { return readAll(QStringLiteral(PADROB_SOURCE_DIR "/models/pendulum.pad")); }

/// 1-based line of the first line of `text` that starts with `prefix`.
int lineStartingWith(const QString& text, const QString& prefix)
{
    const QStringList lines = text.split(u'\n');
    for (int i = 0; i < lines.size(); ++i) {
        if (lines[i].startsWith(prefix)) return i + 1;
    }
    return 0;
}

/// The format the highlighter gave to UTF-16 offset `at` of `block`.
QTextCharFormat formatAt(const QTextBlock& block, int at)
{
    for (const QTextLayout::FormatRange& r : block.layout()->formats()) {
        if (at >= r.start && at < r.start + r.length) return r.format;
    }
    return {};
}

const solver::Diagnostic* findCode(const std::vector<solver::Diagnostic>& diags, const char* code)
{
    for (const solver::Diagnostic& d : diags) {
        if (d.code == code) return &d;
    }
    return nullptr;
}

/// Waits until the panel's current text is checked.
bool waitChecked(EditorPanel& panel, int timeoutMs = 10000)
{
    QDeadlineTimer deadline(timeoutMs);
    while (panel.isChecking() && !deadline.hasExpired()) QTest::qWait(10);
    return !panel.isChecking();
}

/// Types `text` into `w` as key presses (a newline is the Return key).
void type(QWidget* w, const QString& text)
{
    const QStringList lines = text.split(u'\n');
    for (int i = 0; i < lines.size(); ++i) {
        if (i > 0) QTest::keyClick(w, Qt::Key_Return);
        if (!lines[i].isEmpty()) QTest::keyClicks(w, lines[i]);
    }
}

}  // namespace

class EditorTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanup();

    void highlightingFormatsKeywordsNumbersIdsStringsComments();
    void completionOffersKeywordsForAPrefix();
    void goToLineCountsCharactersNotUtf16Units();

    void decimalCommaIsUnderlinedListedAndRefusedByApply();
    void jointWithoutSideLinesIsReportedOnItsLine();
    void applyWaitsForTheCheckOfNewText();
    void junkAndBigFilesKeepTheEditorResponsive();

    void saveSaveAsOpenRoundTrip();
    void crlfAndUtf8ArePreserved();
    void openRejectsMissingFoldersAndBinaryFiles();
    void saveIntoAReadOnlyFolderFailsAndKeepsTheOldFile();
    void saveOverAReadOnlyFileFails();

    void recoveryCopyWhileModifiedRemovedAfterSave();
    void recoveryLeftByACrashIsListedAndRestored();
    void externalChangesAndDeletionAreSignalled();

    void spanishAtRunTimeKeepsTheModelLanguage();

private:
    QString m_screenshots;
};

void EditorTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("padrob-tests"));
    QCoreApplication::setApplicationName(QStringLiteral("studio-editor-test"));
    QDir(ModelDocument::recoveryDirectory()).removeRecursively();
    m_screenshots = QStringLiteral(PADROB_SCREENSHOT_DIR);
    QVERIFY(QDir().mkpath(m_screenshots));
    QVERIFY(!pendulumText().isEmpty());
    // the tests read English texts, whatever the system's locale
    QVERIFY(i18n::install("en"));
}

void EditorTest::cleanup() { QToolTip::hideText(); }

// ---- editor -----------------------------------------------------------------------

void EditorTest::highlightingFormatsKeywordsNumbersIdsStringsComments()
{
    CodeEditor editor;
    editor.setPlainText(QStringLiteral("c 12 qi 0.1 NAME \"pivot\" // the pin\n"
                                       "GRAVITY 0 0 -9.81\n"
                                       "G 3 B 1 SPHERE 0.05 # bob\n"));
    const ModelHighlighter* h = editor.highlighter();
    const QTextBlock b0 = editor.document()->findBlockByNumber(0);
    const QTextBlock b1 = editor.document()->findBlockByNumber(1);
    const QTextBlock b2 = editor.document()->findBlockByNumber(2);

    const QTextCharFormat statement = formatAt(b0, 0);  // c
    const QTextCharFormat id = formatAt(b0, 2);         // 12
    const QTextCharFormat option = formatAt(b0, 5);     // qi
    const QTextCharFormat number = formatAt(b0, 8);     // 0.1
    const QTextCharFormat string = formatAt(b0, 18);    // "pivot"
    const QTextCharFormat comment = formatAt(b0, 28);   // // the pin
    QCOMPARE(statement.foreground(), h->format(ModelHighlighter::Role::StatementKeyword).foreground());
    QCOMPARE(statement.fontWeight(), int(QFont::Bold));
    QCOMPARE(id.foreground(), h->format(ModelHighlighter::Role::Id).foreground());
    QCOMPARE(option.foreground(), h->format(ModelHighlighter::Role::OptionKeyword).foreground());
    QCOMPARE(number.foreground(), h->format(ModelHighlighter::Role::Number).foreground());
    QCOMPARE(string.foreground(), h->format(ModelHighlighter::Role::String).foreground());
    QCOMPARE(comment.foreground(), h->format(ModelHighlighter::Role::Comment).foreground());
    QVERIFY(comment.fontItalic());
    // all different
    const QList<QColor> colors = {statement.foreground().color(), id.foreground().color(), option.foreground().color(),
                                  number.foreground().color(), string.foreground().color(), comment.foreground().color()};
    for (int i = 0; i < colors.size(); ++i) {
        for (int j = i + 1; j < colors.size(); ++j) QVERIFY2(colors[i] != colors[j], qPrintable(QString("%1 %2").arg(i).arg(j)));
    }
    // GRAVITY's numbers are values, not ids; G's id and its body reference are ids
    QCOMPARE(formatAt(b1, 0).foreground(), h->format(ModelHighlighter::Role::StatementKeyword).foreground());
    QCOMPARE(formatAt(b1, 8).foreground(), h->format(ModelHighlighter::Role::Number).foreground());
    QCOMPARE(formatAt(b2, 2).foreground(), h->format(ModelHighlighter::Role::Id).foreground());       // 3
    QCOMPARE(formatAt(b2, 4).foreground(), h->format(ModelHighlighter::Role::OptionKeyword).foreground());  // B
    QCOMPARE(formatAt(b2, 6).foreground(), h->format(ModelHighlighter::Role::Id).foreground());       // 1
    QCOMPARE(formatAt(b2, 8).foreground(), h->format(ModelHighlighter::Role::OptionKeyword).foreground());  // SPHERE
    QCOMPARE(formatAt(b2, 15).foreground(), h->format(ModelHighlighter::Role::Number).foreground());  // 0.05
    QCOMPARE(formatAt(b2, 20).foreground(), h->format(ModelHighlighter::Role::Comment).foreground()); // # bob
    // a decimal comma is no number; a string keeps its comment signs
    editor.setPlainText(QStringLiteral("B 4 4,38325 NAME \"a // b\""));
    const QTextBlock b = editor.document()->firstBlock();
    QVERIFY(formatAt(b, 4).foreground() != h->format(ModelHighlighter::Role::Number).foreground());
    QCOMPARE(formatAt(b, 20).foreground(), h->format(ModelHighlighter::Role::String).foreground());
}

void EditorTest::completionOffersKeywordsForAPrefix()
{
    CodeEditor editor;
    editor.resize(500, 300);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    editor.setFocus();

    // two letters of a word bring the popup by themselves, case-insensitively
    QTest::keyClicks(&editor, QStringLiteral("G 4 B 1 sp"));
    QCompleter* c = editor.completer();
    QTRY_VERIFY(c->popup()->isVisible());
    QStringList offered;
    for (int i = 0; i < c->completionCount(); ++i) {
        c->setCurrentRow(i);
        offered << c->currentCompletion();
    }
    QCOMPARE(offered, QStringList({QStringLiteral("SPHERE"), QStringLiteral("SPRING")}));
    c->setCurrentRow(0);
    c->popup()->setCurrentIndex(c->completionModel()->index(0, 0));
    QTest::keyClick(c->popup(), Qt::Key_Return);
    QCOMPARE(editor.toPlainText(), QStringLiteral("G 4 B 1 SPHERE"));
    QVERIFY(!c->popup()->isVisible());

    // Ctrl+Space after one letter
    QTest::keyClicks(&editor, QStringLiteral(" v"));
    QVERIFY(!c->popup()->isVisible());
    QTest::keyClick(&editor, Qt::Key_Space, Qt::ControlModifier);
    QTRY_VERIFY(c->popup()->isVisible());
    QCOMPARE(c->completionCount(), 5);  // VALVE VI VMAX VMIN VOLUME
    QTest::keyClick(c->popup(), Qt::Key_Escape);
    QTRY_VERIFY(!c->popup()->isVisible());

    // nothing in comments, numbers or a word that is already the keyword
    editor.clear();
    QTest::keyClicks(&editor, QStringLiteral("// pos"));
    QVERIFY(!c->popup()->isVisible());
    QCOMPARE(editor.completionPrefix(), QString());
    editor.clear();
    QTest::keyClicks(&editor, QStringLiteral("C 1 12"));
    QVERIFY(!c->popup()->isVisible());
    editor.clear();
    QTest::keyClicks(&editor, QStringLiteral("C 1 QI"));
    QVERIFY(!c->popup()->isVisible());
    QCOMPARE(editor.completionPrefix(), QStringLiteral("QI"));

    // the keyword list is the language's
    // (fluid power and contact too: FLUID, PUMP … CYL, HMOTOR … CONTACT, MU, NOCONTACT)
    for (const char* kw : {"GRAVITY", "RESTITUTION", "CL1", "PRESSURE", "ELLIPSOID", "DEG", "TABLE", "LOCAL", "FLUID",
                           "BULK", "LAMINAR", "FLOW", "MARGIN", "HMOTOR", "VALVE", "COMP", "POST", "DEAD", "DISP",
                           "CONTACT", "MU", "NOCONTACT"}) {
        QVERIFY2(modelKeywords().contains(QLatin1String(kw)), kw);
    }
    QVERIFY(isStatementKeyword(u"CONTACT"));
    QVERIFY(isStatementKeyword(u"FLUID"));
    QVERIFY(!isStatementKeyword(u"MU"));
}

void EditorTest::goToLineCountsCharactersNotUtf16Units()
{
    CodeEditor editor;
    // "😀" is two UTF-16 units but one character (the solver's columns)
    editor.setPlainText(QStringLiteral("B 1 NAME \"😀x\" QQ\nC 2\n"));
    editor.goToLine(1, 15);  // the Q of QQ: B,space,1,space,NAME(4),space,",😀,x,",space → 15
    QCOMPARE(editor.cursorLine(), 1);
    QCOMPARE(editor.cursorColumn(), 15);
    QCOMPARE(editor.textCursor().positionInBlock(), 15);  // 14 characters before, 15 UTF-16 units
    QCOMPARE(editor.textCursor().block().text().mid(15, 2), QStringLiteral("QQ"));
    editor.goToLine(99, 99);  // clamped
    QCOMPARE(editor.cursorLine(), editor.blockCount());
    editor.goToLine(2, 3);
    QCOMPARE(editor.cursorLine(), 2);
    QCOMPARE(editor.cursorColumn(), 3);
}

// ---- live diagnostics and apply ---------------------------------------------------------

void EditorTest::decimalCommaIsUnderlinedListedAndRefusedByApply()
{
    EditorPanel panel;
    panel.setCheckDelay(100);
    panel.resize(1000, 640);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));

    int appliedCount = 0;
    std::shared_ptr<const ModelBundle> appliedBundle;
    connect(&panel, &EditorPanel::applied, this, [&](std::shared_ptr<const ModelBundle> b) {
        ++appliedCount;
        appliedBundle = std::move(b);
    });
    QSignalSpy diagSpy(&panel, &EditorPanel::diagnosticsChanged);

    const QString pendulum = pendulumText();
    panel.setText(pendulum);
    QVERIFY(waitChecked(panel));
    QCOMPARE(panel.errorCount(), 0);
    QVERIFY(panel.applyButton()->isEnabled());
    QTest::mouseClick(panel.applyButton(), Qt::LeftButton);
    QCOMPARE(appliedCount, 1);
    QVERIFY(appliedBundle);
    QCOMPARE(appliedBundle->model->nb, 1);
    const auto firstGood = panel.lastGood();
    QCOMPARE(firstGood, appliedBundle);

    // type "4,38325" over the bob's mass, as a modeler would
    const int line = lineStartingWith(pendulum, QStringLiteral("B 1 1.0"));
    QVERIFY(line > 0);
    CodeEditor* editor = panel.editor();
    editor->goToLine(line, 5);
    QTextCursor sel = editor->textCursor();
    sel.movePosition(QTextCursor::Right, QTextCursor::KeepAnchor, 3);
    QCOMPARE(sel.selectedText(), QStringLiteral("1.0"));
    editor->setTextCursor(sel);
    diagSpy.clear();
    QTest::keyClicks(editor, QStringLiteral("4,38325"));
    QVERIFY(panel.isChecking());
    QVERIFY(diagSpy.wait(5000));
    QVERIFY(!panel.isChecking());
    QVERIFY(panel.errorCount() >= 1);
    QCOMPARE(diagSpy.last().at(0).toInt(), panel.errorCount());

    const solver::Diagnostic* d = findCode(panel.diagnostics(), "decimal-comma");
    QVERIFY(d);
    QCOMPARE(d->pos.line, line);
    QCOMPARE(d->pos.column, 5);
    const QString message = QString::fromStdString(d->message);
    QVERIFY(message.contains(QStringLiteral("4,38325")));

    // the problems list: that line:col, message and hint
    ProblemsView* problems = panel.problemsView();
    QTreeWidgetItem* item = nullptr;
    for (int i = 0; i < problems->problemCount(); ++i) {
        QTreeWidgetItem* it = problems->topLevelItem(i);
        if (it->data(0, ProblemsView::CodeRole).toString() == QStringLiteral("decimal-comma")) item = it;
    }
    QVERIFY(item);
    QCOMPARE(item->text(ProblemsView::LocationColumn), QStringLiteral("%1:5").arg(line));
    QCOMPARE(item->text(ProblemsView::MessageColumn), message);
    QCOMPARE(item->text(ProblemsView::HintColumn), QString::fromStdString(d->hint));
    QVERIFY(item->text(ProblemsView::HintColumn).contains(QStringLiteral("4.38325")));

    // the editor: a red wavy underline over the token, its tooltip the message
    const int pos = editor->positionOf(line, 5);
    bool underlined = false;
    for (const QTextEdit::ExtraSelection& s : editor->extraSelections()) {
        if (s.format.underlineStyle() != QTextCharFormat::WaveUnderline) continue;
        if (s.cursor.selectionStart() == pos && s.cursor.selectionEnd() == pos + 7) {
            underlined = true;
            QCOMPARE(s.format.underlineColor(), QColor(0xd3, 0x2f, 0x2f));
            QCOMPARE(s.cursor.selectedText(), QStringLiteral("4,38325"));
        }
    }
    QVERIFY(underlined);
    QVERIFY(editor->diagnosticToolTipAt(pos + 2).contains(message.toHtmlEscaped()));
    QVERIFY(editor->diagnosticToolTipAt(pos + 2).contains(QString::fromStdString(d->hint).toHtmlEscaped()));
    QVERIFY(editor->diagnosticToolTipAt(editor->positionOf(line, 1)).isEmpty());

    // hovering shows it
    QTextCursor at(editor->document());
    at.setPosition(pos + 2);
    const QPoint p = editor->cursorRect(at).center() + QPoint(2, 0);
    QHelpEvent help(QEvent::ToolTip, p, editor->viewport()->mapToGlobal(p));
    QApplication::sendEvent(editor->viewport(), &help);
    QTRY_VERIFY(QToolTip::isVisible());
    QVERIFY(QToolTip::text().contains(message.toHtmlEscaped()));
    // the tooltip is a window of its own: grab the screen around the panel
    QTest::qWait(300);
    const QRect area(panel.mapToGlobal(QPoint(0, 0)), panel.size());
    QVERIFY(panel.screen()->grabWindow(0, area.x(), area.y(), area.width(), area.height())
                .save(m_screenshots + QStringLiteral("/editor_decimal_comma_tooltip.png")));

    // Apply is refused: disabled, and apply() explains; the last good model stays
    QVERIFY(!panel.applyButton()->isEnabled());
    panel.apply();
    QCOMPARE(appliedCount, 1);
    QCOMPARE(panel.lastGood(), firstGood);
    QVERIFY(panel.statusText().contains(QStringLiteral("Not applied")));

    // clicking the problem moves the cursor there
    editor->goToLine(1, 1);
    problems->scrollToItem(item);
    QTest::mouseClick(problems->viewport(), Qt::LeftButton, {}, problems->visualItemRect(item).center());
    QCOMPARE(editor->cursorLine(), line);
    QCOMPARE(editor->cursorColumn(), 5);
    editor->goToLine(1, 1);
    emit problems->itemActivated(item, 0);  // Enter / double-click
    QCOMPARE(editor->cursorLine(), line);

    // a picture of the error for people
    editor->goToLine(line, 5);
    QTest::qWait(50);
    const QString shot = m_screenshots + QStringLiteral("/editor_decimal_comma.png");
    QVERIFY(panel.grab().save(shot));

    // fix it (undo the typing) → no errors → Apply gives the model
    diagSpy.clear();
    while (panel.text() != pendulum && editor->document()->isUndoAvailable()) editor->undo();
    QCOMPARE(panel.text(), pendulum);
    QVERIFY(diagSpy.wait(5000));
    QCOMPARE(diagSpy.last().at(0).toInt(), 0);
    QCOMPARE(panel.errorCount(), 0);
    QVERIFY(editor->diagnosticSelections().isEmpty());
    QCOMPARE(problems->problemCount(), 0);
    QVERIFY(panel.applyButton()->isEnabled());
    QTest::mouseClick(panel.applyButton(), Qt::LeftButton);
    QCOMPARE(appliedCount, 2);
    QVERIFY(appliedBundle && appliedBundle != firstGood);
    QCOMPARE(appliedBundle->model->nb, 1);
    QCOMPARE(panel.lastGood(), appliedBundle);
}

void EditorTest::jointWithoutSideLinesIsReportedOnItsLine()
{
    EditorPanel panel;
    panel.setCheckDelay(50);
    const QString pendulum = pendulumText();
    panel.setText(pendulum);
    QVERIFY(waitChecked(panel));
    QCOMPARE(panel.errorCount(), 0);

    QSignalSpy diagSpy(&panel, &EditorPanel::diagnosticsChanged);
    CodeEditor* editor = panel.editor();
    editor->moveCursor(QTextCursor::End);
    QTest::keyClicks(editor, QStringLiteral("C 99"));
    QVERIFY(diagSpy.wait(5000));
    const int line = editor->blockCount();
    QVERIFY(panel.errorCount() >= 1);
    const solver::Diagnostic* d = findCode(panel.diagnostics(), "missing-joint-line");
    QVERIFY(d);
    QCOMPARE(d->pos.line, line);
    QVERIFY(panel.problemsView()->problemCount() >= 1);
    QCOMPARE(panel.problemsView()->topLevelItem(panel.problemsView()->problemCount() - 1)->data(0, ProblemsView::LineRole).toInt(), line);
    // the underline is on that line, and the gutter tooltip tells it too
    bool found = false;
    for (const QTextEdit::ExtraSelection& s : editor->diagnosticSelections()) {
        if (s.cursor.blockNumber() == line - 1) found = true;
    }
    QVERIFY(found);
    // applying now emits nothing
    int applied = 0;
    connect(&panel, &EditorPanel::applied, this, [&] { ++applied; });
    panel.apply();
    QCOMPARE(applied, 0);
    QVERIFY(!panel.lastGood());
}

void EditorTest::applyWaitsForTheCheckOfNewText()
{
    EditorPanel panel;
    panel.setCheckDelay(10000);  // only apply() starts the check
    int applied = 0;
    std::shared_ptr<const ModelBundle> bundle;
    connect(&panel, &EditorPanel::applied, this, [&](std::shared_ptr<const ModelBundle> b) {
        ++applied;
        bundle = std::move(b);
    });
    panel.setText(QString::fromUtf8(readBytes(QStringLiteral(PADROB_SOURCE_DIR "/models/double_pendulum.pad"))));
    QVERIFY(panel.isChecking());
    panel.apply();
    QTRY_COMPARE_WITH_TIMEOUT(applied, 1, 10000);
    QCOMPARE(bundle->model->nb, 2);
    QCOMPARE(panel.checkedBundle(), bundle);
}

void EditorTest::junkAndBigFilesKeepTheEditorResponsive()
{
    EditorPanel panel;
    panel.setCheckDelay(0);
    panel.resize(900, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));

    // the GUI thread must keep running while a big text is checked
    QElapsedTimer clock;
    qint64 last = 0, worstGap = 0;
    QTimer ticker;
    connect(&ticker, &QTimer::timeout, this, [&] {
        worstGap = std::max(worstGap, clock.elapsed() - last);
        last = clock.elapsed();
    });

    // junk: 20,000 lines of an unknown keyword (10,000 diagnostics, then a note)
    QString junk;
    for (int i = 0; i < 20000; ++i) junk += QStringLiteral("X %1 2 3\n").arg(i);
    QElapsedTimer total;
    total.start();
    panel.setText(junk);
    const qint64 setTextMs = total.elapsed();
    clock.start();
    ticker.start(10);
    QSignalSpy diagSpy(&panel, &EditorPanel::diagnosticsChanged);
    QVERIFY(diagSpy.wait(60000));
    QTest::qWait(50);
    ticker.stop();
    qInfo("junk: setText %lld ms, check + display %lld ms, longest GUI pause %lld ms, %d problems, %d underlines",
          setTextMs, clock.elapsed(), worstGap, panel.problemsView()->problemCount(),
          int(panel.editor()->diagnosticSelections().size()));
    QVERIFY(panel.errorCount() >= 10000);
    QCOMPARE(panel.problemsView()->problemCount(), int(panel.diagnostics().size()));
    QVERIFY(findCode(panel.diagnostics(), "too-many-diagnostics"));
    QVERIFY(panel.editor()->diagnosticSelections().size() <= 1000);
    // typing stays quick with all those underlines
    panel.editor()->goToLine(100, 1);
    QElapsedTimer typing;
    typing.start();
    QTest::keyClicks(panel.editor(), QStringLiteral("// note "));
    qInfo("junk: typing 8 keys %lld ms", typing.elapsed());

    // big and valid: a chain of 2,000 bodies (some 400 kB)
    QString chain = QStringLiteral("GRAVITY 0 0 -9.81\n");
    for (int i = 1; i <= 2000; ++i) {
        chain += QStringLiteral("B %1 1.0 0.01 0.01 0.01 NAME \"link %1\"\n").arg(i);
        chain += QStringLiteral("C %1 QI 0.01\nB1 %2 P1 0 0 -0.05 A1 1 0 0 R1 0 0 -1\nB2 %1 P2 0 0 0.05 A2 1 0 0 R2 0 0 -1\n")
                     .arg(i)
                     .arg(i - 1);
    }
    total.restart();
    panel.setText(chain);
    const qint64 chainSetText = total.elapsed();
    worstGap = 0;
    last = 0;
    clock.restart();
    ticker.start(10);
    diagSpy.clear();
    panel.checkNow();
    QVERIFY(panel.isChecking());  // it runs on the worker thread: checkNow() does not wait
    QVERIFY(diagSpy.wait(120000));
    QTest::qWait(50);
    ticker.stop();
    qInfo("chain: setText %lld ms, check + display %lld ms, longest GUI pause %lld ms, %d errors",
          chainSetText, clock.elapsed(), worstGap, panel.errorCount());
    QVERIFY(worstGap < 3000);  // loose: the machine is shared
    QCOMPARE(panel.errorCount(), 0);
    QVERIFY(panel.checkedBundle());
    QCOMPARE(panel.checkedBundle()->model->nb, 2000);
}

// ---- files -------------------------------------------------------------------------------

void EditorTest::saveSaveAsOpenRoundTrip()
{
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    EditorPanel panel;
    QSignalSpy modSpy(&panel, &EditorPanel::modificationChanged);
    QSignalSpy pathSpy(&panel, &EditorPanel::filePathChanged);
    QCOMPARE(panel.displayName(), QStringLiteral("Untitled"));
    QVERIFY(!panel.isModified());

    panel.setText(pendulumText());
    QVERIFY(panel.isModified());
    QCOMPARE(modSpy.count(), 1);
    QString error;
    QVERIFY(!panel.save(&error));  // untitled: Save As first
    QVERIFY(!error.isEmpty());

    const QString a = tmp.filePath(QStringLiteral("a.pad"));
    QVERIFY2(panel.saveAs(a, &error), qPrintable(error));
    QCOMPARE(panel.filePath(), a);
    QCOMPARE(panel.displayName(), QStringLiteral("a.pad"));
    QCOMPARE(pathSpy.count(), 1);
    QVERIFY(!panel.isModified());
    QCOMPARE(readAll(a), pendulumText());

    // edit, undo back to the saved text: not modified again
    panel.editor()->moveCursor(QTextCursor::End);
    type(panel.editor(), QStringLiteral("// more\n"));
    QVERIFY(panel.isModified());
    int steps = 0;
    for (; panel.text() != pendulumText() && steps < 10; ++steps) panel.undo();
    QCOMPARE(panel.text(), pendulumText());
    QVERIFY(!panel.isModified());
    while (steps-- > 0) panel.redo();
    QVERIFY(panel.isModified());
    QVERIFY2(panel.save(&error), qPrintable(error));
    QVERIFY(!panel.isModified());
    QCOMPARE(readAll(a), pendulumText() + QStringLiteral("// more\n"));

    EditorPanel other;
    QVERIFY2(other.open(a, &error), qPrintable(error));
    QCOMPARE(other.text(), panel.text());
    QCOMPARE(other.filePath(), a);
    QVERIFY(!other.isModified());
    QVERIFY(!other.editor()->document()->isUndoAvailable());
    QVERIFY(waitChecked(other));
    QCOMPARE(other.errorCount(), 0);
}

void EditorTest::crlfAndUtf8ArePreserved()
{
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("crlf.pad"));
    const QByteArray original = "B 1 1 1 1 1 NAME \"MU\xC3\x91" "ECA\"\r\nGRAVITY 0 0 -9.81\r\n";
    QVERIFY(writeAll(path, original));
    ModelDocument doc;
    QString error;
    QVERIFY2(doc.open(path, &error), qPrintable(error));
    QVERIFY(!doc.text().contains(u'\r'));
    QVERIFY(doc.text().contains(QStringLiteral("MUÑECA")));
    QVERIFY(!doc.readAsLatin1());
    doc.setText(doc.text() + QStringLiteral("// end\n"));
    QVERIFY2(doc.save(&error), qPrintable(error));
    QCOMPARE(readBytes(path), original + "// end\r\n");

    // Latin-1 is read (as the solver does) and written back as UTF-8
    const QString latin = tmp.filePath(QStringLiteral("latin1.pad"));
    QVERIFY(writeAll(latin, "B 1 NAME \"MU\xD1" "ECA\"\n"));
    QVERIFY(doc.open(latin, &error));
    QVERIFY(doc.readAsLatin1());
    QVERIFY(doc.text().contains(QStringLiteral("MUÑECA")));
    QVERIFY(doc.saveAs(latin, &error));
    QCOMPARE(readBytes(latin), QByteArray("B 1 NAME \"MU\xC3\x91" "ECA\"\n"));
}

void EditorTest::openRejectsMissingFoldersAndBinaryFiles()
{
    QTemporaryDir tmp;
    EditorPanel panel;
    panel.setText(QStringLiteral("GRAVITY 0 0 -9.81\n"));
    QString error;
    QVERIFY(!panel.open(tmp.filePath(QStringLiteral("missing.pad")), &error));
    QVERIFY(error.contains(QStringLiteral("does not exist")));
    QVERIFY(!panel.open(tmp.path(), &error));
    QVERIFY(error.contains(QStringLiteral("folder")));
    const QString binary = tmp.filePath(QStringLiteral("bin.pad"));
    QVERIFY(writeAll(binary, QByteArray("B 1\0\0\x01\x02", 7)));
    QVERIFY(!panel.open(binary, &error));
    QVERIFY(error.contains(QStringLiteral("not a text file")));
    // the document is untouched
    QCOMPARE(panel.text(), QStringLiteral("GRAVITY 0 0 -9.81\n"));
    QVERIFY(panel.isModified());
    QVERIFY(panel.filePath().isEmpty());
    // saving into a folder that does not exist, or where nobody may write (even root)
    QVERIFY(!panel.saveAs(tmp.filePath(QStringLiteral("no/such/dir/x.pad")), &error));
    QVERIFY(error.contains(QStringLiteral("does not exist")));
    error.clear();
    QVERIFY(!panel.saveAs(QStringLiteral("/proc/padrob-editor-test.pad"), &error));
    QVERIFY2(error.startsWith(QStringLiteral("Cannot save")), qPrintable(error));
    QVERIFY(!QFile::exists(QStringLiteral("/proc/padrob-editor-test.pad")));
    QVERIFY(panel.filePath().isEmpty());
    QVERIFY(panel.isModified());
}

void EditorTest::saveIntoAReadOnlyFolderFailsAndKeepsTheOldFile()
{
    if (::geteuid() == 0) {
        // root writes whatever the modes say: the test runs as an ordinary user
        const padrob_test::UserRun r = padrob_test::runAsUser({QStringLiteral("saveIntoAReadOnlyFolderFailsAndKeepsTheOldFile")}, {{"QT_QPA_PLATFORM", "offscreen"}});
        QVERIFY2(r.ran && r.exitCode == 0, qPrintable(r.output));
        QVERIFY2(r.output.contains(QStringLiteral("PASS   : EditorTest::saveIntoAReadOnlyFolderFailsAndKeepsTheOldFile()")), qPrintable(r.output));
        return;
    }
    QTemporaryDir tmp;
    const QString dir = tmp.filePath(QStringLiteral("locked"));
    QVERIFY(QDir().mkpath(dir));
    const QString path = dir + QStringLiteral("/model.pad");
    const QByteArray original = pendulumText().toUtf8();
    QVERIFY(writeAll(path, original));

    EditorPanel panel;
    QString error;
    QVERIFY(panel.open(path, &error));
    panel.setText(QStringLiteral("B 1 2 0.1 0.1 0.1\n"));
    QVERIFY(QFile::setPermissions(dir, QFile::ReadOwner | QFile::ExeOwner));
    const bool saved = panel.save(&error);
    const bool savedElsewhere = panel.saveAs(dir + QStringLiteral("/new.pad"), &error);
    QFile::setPermissions(dir, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    QVERIFY(!saved);
    QVERIFY(!savedElsewhere);
    QVERIFY2(error.contains(QStringLiteral("not writable")), qPrintable(error));
    QCOMPARE(readBytes(path), original);  // intact
    QVERIFY(!QFile::exists(dir + QStringLiteral("/new.pad")));
    QVERIFY(panel.isModified());
    QCOMPARE(panel.filePath(), path);
}

void EditorTest::saveOverAReadOnlyFileFails()
{
    if (::geteuid() == 0) {
        // root writes whatever the modes say: the test runs as an ordinary user
        const padrob_test::UserRun r = padrob_test::runAsUser({QStringLiteral("saveOverAReadOnlyFileFails")}, {{"QT_QPA_PLATFORM", "offscreen"}});
        QVERIFY2(r.ran && r.exitCode == 0, qPrintable(r.output));
        QVERIFY2(r.output.contains(QStringLiteral("PASS   : EditorTest::saveOverAReadOnlyFileFails()")), qPrintable(r.output));
        return;
    }
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("ro.pad"));
    QVERIFY(writeAll(path, "GRAVITY 0 0 -9.81\n"));
    ModelDocument doc;
    QString error;
    QVERIFY(doc.open(path, &error));
    doc.setText(QStringLiteral("GRAVITY 0 0 -1\n"));
    QVERIFY(QFile::setPermissions(path, QFile::ReadOwner));
    QVERIFY(!doc.save(&error));
    QVERIFY2(error.contains(QStringLiteral("read-only")), qPrintable(error));
    QCOMPARE(readBytes(path), QByteArray("GRAVITY 0 0 -9.81\n"));
    QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
}

// ---- recovery and the file watcher ------------------------------------------------------

void EditorTest::recoveryCopyWhileModifiedRemovedAfterSave()
{
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("pendulum.pad"));
    QVERIFY(writeAll(path, pendulumText().toUtf8()));

    QString recovery;
    {
        EditorPanel panel;
        ModelDocument* doc = panel.document();
        QCOMPARE(doc->recoveryInterval(), 30000);
        doc->setRecoveryInterval(50);
        QString error;
        QVERIFY(panel.open(path, &error));
        recovery = doc->recoveryFilePath();
        QVERIFY(recovery.startsWith(ModelDocument::recoveryDirectory()));
        QVERIFY(QFileInfo(recovery).fileName().startsWith(QStringLiteral("pendulum-")));
        QTest::qWait(150);
        QVERIFY(!QFile::exists(recovery));  // not modified: no copy

        QSignalSpy written(doc, &ModelDocument::recoveryWritten);
        panel.editor()->moveCursor(QTextCursor::End);
        type(panel.editor(), QStringLiteral("// unsaved work\n"));
        QVERIFY(written.wait(2000));
        QVERIFY(QFile::exists(recovery));
        QCOMPARE(readAll(recovery), panel.text());
        const QString info = QFileInfo(recovery).path() + u'/' + QFileInfo(recovery).completeBaseName() + QStringLiteral(".json");
        const QJsonObject json = QJsonDocument::fromJson(readBytes(info)).object();
        QCOMPARE(json.value(QStringLiteral("path")).toString(), path);
        // this session's own copy is not offered as a crash's
        for (const RecoveryEntry& e : ModelDocument::recoveryEntries()) QVERIFY(e.textFile != recovery);

        // a newer text is written again; saving removes the copy
        type(panel.editor(), QStringLiteral("// more\n"));
        QTRY_COMPARE(readAll(recovery), panel.text());
        QVERIFY(panel.save(&error));
        QVERIFY(!QFile::exists(recovery));
        QVERIFY(!QFile::exists(info));
        QTest::qWait(150);
        QVERIFY(!QFile::exists(recovery));

        // modified, and the modeler closes without saving: the main window discards it
        type(panel.editor(), QStringLiteral("// dropped\n"));
        QVERIFY(written.wait(2000));
        QVERIFY(QFile::exists(recovery));
        panel.discardOwnRecovery();
        QVERIFY(!QFile::exists(recovery));
        QVERIFY(!written.wait(200));  // nothing new to write

        // modified again, then the panel goes (a normal close): removed too
        type(panel.editor(), QStringLiteral("// again\n"));
        QVERIFY(written.wait(2000));
        QVERIFY(QFile::exists(recovery));
    }
    QVERIFY(!QFile::exists(recovery));
    QVERIFY(EditorPanel::recoveryFiles().isEmpty());
}

void EditorTest::recoveryLeftByACrashIsListedAndRestored()
{
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("crashed.pad"));
    QVERIFY(writeAll(path, "GRAVITY 0 0 -9.81\n"));
    // what a crashed session leaves: a copy and its side file, another process id
    const QString dir = ModelDocument::recoveryDirectory();
    QVERIFY(QDir().mkpath(dir));
    const QString textFile = dir + QStringLiteral("/crashed-0123456789abcdef.pad");
    const QString infoFile = dir + QStringLiteral("/crashed-0123456789abcdef.json");
    const QString recovered = QStringLiteral("GRAVITY 0 0 -9.81\nB 1 1 1e-6 1e-6 1e-6\n// typed before the crash\n");
    QVERIFY(writeAll(textFile, recovered.toUtf8()));
    QJsonObject info;
    info[QStringLiteral("path")] = path;
    info[QStringLiteral("name")] = QStringLiteral("crashed.pad");
    info[QStringLiteral("savedAt")] = QStringLiteral("2024-05-01T10:00:00.000Z");
    info[QStringLiteral("pid")] = 999999999;
    QVERIFY(writeAll(infoFile, QJsonDocument(info).toJson()));

    const QList<EditorPanel::Recovery> entries = EditorPanel::recoveryFiles();
    QCOMPARE(entries.size(), 1);
    const EditorPanel::Recovery& e = entries.first();
    QCOMPARE(e.originalPath, path);
    QCOMPARE(e.displayName, QStringLiteral("crashed.pad"));
    QCOMPARE(e.saved, QDateTime(QDate(2024, 5, 1), QTime(10, 0), Qt::UTC));
    QString text, error;
    QVERIFY(ModelDocument::readRecovery(e, &text, &error));
    QCOMPARE(text, recovered);

    {
        EditorPanel panel;
        QVERIFY2(panel.restoreRecovery(e, &error), qPrintable(error));
        QCOMPARE(panel.text(), recovered);
        QCOMPARE(panel.filePath(), path);
        QVERIFY(panel.isModified());  // not saved yet
        // the old copy is replaced by this session's own
        QVERIFY(QFile::exists(panel.document()->recoveryFilePath()));
        QVERIFY(!QFile::exists(textFile) || panel.document()->recoveryFilePath() == textFile);
        QVERIFY(ModelDocument::recoveryEntries().isEmpty());
        QVERIFY(panel.save(&error));
        QCOMPARE(readAll(path), recovered);
        QVERIFY(!QFile::exists(panel.document()->recoveryFilePath()));
    }
    QVERIFY(QDir(dir).entryList({QStringLiteral("*.pad")}, QDir::Files).isEmpty());

    // discarding one
    QVERIFY(writeAll(textFile, "x"));
    QCOMPARE(EditorPanel::recoveryFiles().size(), 1);
    QVERIFY(EditorPanel::recoveryFiles().first().originalPath.isEmpty());  // no side file: untitled
    QVERIFY(EditorPanel::discardRecovery(EditorPanel::recoveryFiles().first()));
    QVERIFY(EditorPanel::recoveryFiles().isEmpty());
}

void EditorTest::externalChangesAndDeletionAreSignalled()
{
    QTemporaryDir tmp;
    const QString path = tmp.filePath(QStringLiteral("watched.pad"));
    QVERIFY(writeAll(path, pendulumText().toUtf8()));
    EditorPanel panel;
    QString error;
    QVERIFY(panel.open(path, &error));
    QSignalSpy spy(&panel, &EditorPanel::fileChangedOnDisk);

    // our own saves are not reported
    panel.setText(panel.text() + QStringLiteral("// mine\n"));
    QVERIFY(panel.save(&error));
    QVERIFY(!spy.wait(600));
    QVERIFY(panel.save(&error));
    QVERIFY(!spy.wait(400));

    // another program writes the file
    const QByteArray theirs = "GRAVITY 0 0 -1.62\n";
    QVERIFY(writeAll(path, theirs));
    QVERIFY(spy.wait(3000));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.first().at(0).toString(), path);
    QCOMPARE(spy.first().at(1).toBool(), false);

    // reload takes it; the text replaced can be undone
    const QString before = panel.text();
    QVERIFY(panel.reload(&error));
    QCOMPARE(panel.text(), QString::fromUtf8(theirs));
    QVERIFY(!panel.isModified());
    panel.undo();
    QCOMPARE(panel.text(), before);
    panel.redo();

    // an editor that saves by renaming a new file over it
    spy.clear();
    const QString temp = tmp.filePath(QStringLiteral("watched.pad.tmp"));
    QVERIFY(writeAll(temp, "GRAVITY 0 0 -3.71\n"));
    QVERIFY(QFile::remove(path));
    QVERIFY(QFile::rename(temp, path));
    QTRY_VERIFY_WITH_TIMEOUT(!spy.isEmpty(), 3000);
    QCOMPARE(spy.last().at(1).toBool(), false);

    // deleted
    QVERIFY(panel.reload(&error));
    spy.clear();
    QVERIFY(QFile::remove(path));
    QVERIFY(spy.wait(3000));
    QCOMPARE(spy.first().at(0).toString(), path);
    QCOMPARE(spy.first().at(1).toBool(), true);
    QVERIFY(!spy.wait(400));  // once

    // and written back by someone
    QVERIFY(writeAll(path, "GRAVITY 0 0 -9.81\n"));
    QVERIFY(spy.wait(3000));
    QCOMPARE(spy.last().at(1).toBool(), false);
}


// The editor changes language while it shows a refused model: the status line, the
// problems list and the underline's tooltip in Spanish (the diagnostics in the current
// language, i18n::message), while the model language stays the same: '.' is the decimal
// point and a decimal comma an error in every language.
void EditorTest::spanishAtRunTimeKeepsTheModelLanguage()
{
    EditorPanel panel;
    panel.setCheckDelay(0);
    panel.resize(900, 700);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const QString pendulum = pendulumText();
    panel.newModel(pendulum);
    QVERIFY(waitChecked(panel));
    QCOMPARE(panel.errorCount(), 0);
    QString comma = pendulum;
    comma.replace(QStringLiteral("\nB 1 1.0"), QStringLiteral("\nB 1 4,38325"));
    panel.setText(comma);
    QVERIFY(waitChecked(panel));
    QVERIFY(panel.errorCount() >= 1);
    panel.apply();
    QVERIFY(panel.statusText().startsWith(QStringLiteral("Not applied")));
    ProblemsView* problems = panel.problemsView();
    QCOMPARE(problems->headerItem()->text(ProblemsView::MessageColumn), QStringLiteral("Message"));

    QVERIFY(i18n::install("es"));
    QTRY_COMPARE(problems->headerItem()->text(ProblemsView::MessageColumn), QStringLiteral("Mensaje"));
    QVERIFY2(panel.statusText().startsWith(QStringLiteral("No aplicado")), qPrintable(panel.statusText()));
    QCOMPARE(panel.applyButton()->text(), QStringLiteral("Aplicar"));
    const solver::Diagnostic* d = findCode(panel.diagnostics(), "decimal-comma");
    QVERIFY(d);
    QTreeWidgetItem* item = nullptr;
    for (int i = 0; i < problems->problemCount(); ++i) {
        QTreeWidgetItem* it = problems->topLevelItem(i);
        if (it->data(0, ProblemsView::CodeRole).toString() == QStringLiteral("decimal-comma")) item = it;
    }
    QVERIFY(item);
    QCOMPARE(item->text(ProblemsView::MessageColumn), i18n::message(*d));
    QCOMPARE(item->text(ProblemsView::HintColumn), i18n::hint(*d));
    const int pos = panel.editor()->positionOf(d->pos.line, d->pos.column);
    const QString tip = panel.editor()->diagnosticToolTipAt(pos + 1);
    QVERIFY2(tip.contains(QStringLiteral("Error")) && tip.contains(i18n::message(*d).toHtmlEscaped()), qPrintable(tip));
    QVERIFY(i18n::hint(*d).isEmpty() || tip.contains(QStringLiteral("Sugerencia:")));
    QVERIFY(panel.grab().save(m_screenshots + QStringLiteral("/editor_decimal_comma_es.png")));
    // the model language is the same in Spanish: '.' parses, ',' is still an error
    panel.setText(pendulum);
    QVERIFY(waitChecked(panel));
    QCOMPARE(panel.errorCount(), 0);
    QCOMPARE(panel.statusText(), QStringLiteral("Sin problemas"));
    panel.setText(comma);
    QVERIFY(waitChecked(panel));
    QVERIFY(findCode(panel.diagnostics(), "decimal-comma"));

    QVERIFY(i18n::install("en"));
    QTRY_COMPARE(problems->headerItem()->text(ProblemsView::MessageColumn), QStringLiteral("Message"));
    QCOMPARE(panel.applyButton()->text(), QStringLiteral("Apply"));
}

QTEST_MAIN(EditorTest)
#include "editor_test.moc"
