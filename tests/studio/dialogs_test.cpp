// The inertia calculator dialog (ide/studio/dialogs/) as a real window: a box against
// its closed form, live edits, the solver's errors, the B line handed to the editor as
// one undo step, and a screenshot.

#include "ide/i18n/language.h"
#include "ide/studio/dialogs/b_statement.h"
#include "ide/studio/dialogs/inertia_dialog.h"
#include "ide/studio/model/model_bundle.h"

#include <QComboBox>
#include <QLabel>
#include <QDir>
#include <QFile>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

using studio::InertiaDialog;

namespace {

// body 1: a 0.2 × 0.4 × 0.6 m box of density 1000 (48 kg); body 2: three solids
const char* kModel = R"(// inertia test
GRAVITY 0 0 -9.81
B 1 40 2 1.5 0.7 NAME "block"   // from a drawing
B 2 10 0.1 0.1 0.1 CG 0 0 0.1 NAME "arm"
C 1 NAME "hinge"
B1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 1 P2 0 0 0.5 A2 1 0 0 R2 0 1 0
C 2
B1 1 P1 0 0 -0.3 A1 0 1 0 R1 0 0 1
B2 2 P2 0 0 0 A2 0 1 0 R2 0 0 1
G 1 B 1 BOX 0.2 0.4 0.6 RHO 1000 COLOR 0.8 0.2 0.1
G 2 B 1 SPHERE 0.05 POS 0 0 0.3
G 21 B 2 CYL 0.05 0.6 POS 0.1 0 0.3 AXIS 1 0 0 ROT 0 0 1 30 RHO 7850
G 22 B 2 PRISM 0.02 0 0 0.1 0 0 0.2 POS 0 0.1 0 AXIS 0 -1 0 MASS 3
G 23 B 2 TUBE 0.04 0.03 0.2 POS 0 0 0.5 MASS 1.5
)";

struct Fixture {
    QTemporaryDir dir;
    QString path;
    std::shared_ptr<const studio::ModelBundle> bundle;
    Fixture()
    {
        path = dir.filePath(QStringLiteral("inertia.pad"));
        QFile f(path);
        if (f.open(QIODevice::WriteOnly)) f.write(kModel);
        f.close();
        solver::Diagnostics diags;
        bundle = studio::makeBundle(QString::fromUtf8(kModel), path, diags);
        for (const solver::Diagnostic& d : diags) qWarning("%s", d.format().c_str());
    }
};

void edit(QTableWidget* t, int row, int column, const QString& text) { t->item(row, column)->setText(text); }

bool near(double a, double b, double tol = 1e-12) { return std::abs(a - b) <= tol * (1 + std::abs(b)); }

}  // namespace

class DialogsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void boxMatchesTheClosedForm();
    void editingTheDensityUpdatesLive();
    void negativeDensityShowsTheSolversError();
    void badNumbersAndDimensionsShowErrors();
    void tableRoundTripMatchesTheCalculator();
    void replaceButtonEmitsTheBLine();
    void applyBLineIsOneUndoStep();
    void applyBLineInsertsAfterTheLastBStatement();
    void bStatementKeepsNameAndComment();
    void screenshot();
    void spanishAtRunTime();
};

// the tests read English texts and '.' numbers, whatever the system's locale
void DialogsTest::initTestCase() { QVERIFY(i18n::install("en")); }

void DialogsTest::boxMatchesTheClosedForm()
{
    Fixture fx;
    QVERIFY(fx.bundle);
    InertiaDialog dialog(fx.bundle);
    QCOMPARE(dialog.bodyId(), 1);
    QCOMPARE(dialog.bodyCombo()->count(), 2);
    QTableWidget* t = dialog.solidsTable();
    QCOMPARE(t->rowCount(), 1);  // G 2 has neither MASS nor RHO: not a solid
    QCOMPARE(t->item(0, InertiaDialog::ShapeColumn)->text(), QStringLiteral("BOX"));
    QCOMPARE(t->item(0, InertiaDialog::DimsColumn)->text(), QStringLiteral("0.2 0.4 0.6"));
    QCOMPARE(t->item(0, InertiaDialog::ValueColumn)->text(), QStringLiteral("1000"));
    QVERIFY(dialog.errorText().isEmpty());
    QVERIFY(dialog.result());
    const solver::MassProperties& p = *dialog.result();
    const double m = 1000 * 0.2 * 0.4 * 0.6;
    QVERIFY(near(p.mass, 48));
    QVERIFY(near(p.inertia(0, 0), m * (0.4 * 0.4 + 0.6 * 0.6) / 12));  // 2.08
    QVERIFY(near(p.inertia(1, 1), m * (0.2 * 0.2 + 0.6 * 0.6) / 12));  // 1.6
    QVERIFY(near(p.inertia(2, 2), m * (0.2 * 0.2 + 0.4 * 0.4) / 12));  // 0.8
    QVERIFY(std::abs(p.inertia(0, 1)) < 1e-15 && std::abs(p.inertia(1, 2)) < 1e-15 && std::abs(p.inertia(0, 2)) < 1e-15);
    QVERIFY(p.com.norm() < 1e-15);
    QCOMPARE(t->item(0, InertiaDialog::MassColumn)->text(), QStringLiteral("48"));
    QCOMPARE(dialog.computedStatement(), QStringLiteral("B 1 48 2.08 1.6 0.8 0 0 0 CG 0 0 0"));
    QCOMPARE(dialog.fileBLine(), QStringLiteral("B 1 40 2 1.5 0.7 NAME \"block\"   // from a drawing"));
    QCOMPARE(dialog.computedBLine(), QStringLiteral("B 1 48 2.08 1.6 0.8 0 0 0 CG 0 0 0 NAME \"block\"  // from a drawing"));
    QCOMPARE(dialog.bStatementLine(), 3);
    QVERIFY(dialog.replaceButton()->isEnabled());
}

void DialogsTest::editingTheDensityUpdatesLive()
{
    Fixture fx;
    InertiaDialog dialog(fx.bundle);
    QTableWidget* t = dialog.solidsTable();
    edit(t, 0, InertiaDialog::ValueColumn, QStringLiteral("2000"));
    QVERIFY(dialog.result());
    QVERIFY(near(dialog.result()->mass, 96));
    QVERIFY(near(dialog.result()->inertia(0, 0), 2 * 2.08));
    QVERIFY(dialog.computedStatement().startsWith(QLatin1String("B 1 96 4.16 3.2 1.6 ")));
    // a mass instead of a density: 12 kg of the same box
    auto* kind = qobject_cast<QComboBox*>(t->cellWidget(0, InertiaDialog::KindColumn));
    QVERIFY(kind);
    kind->setCurrentIndex(kind->findData(QStringLiteral("MASS")));
    edit(t, 0, InertiaDialog::ValueColumn, QStringLiteral("12"));
    QVERIFY(dialog.result());
    QVERIFY(near(dialog.result()->mass, 12));
    QVERIFY(near(dialog.result()->inertia(2, 2), 12 * 0.2 / 12));
    // moved up by 0.1 m: the centre of mass follows
    edit(t, 0, InertiaDialog::PosColumn, QStringLiteral("0 0 0.1"));
    QVERIFY(near(dialog.result()->com.z(), 0.1));
    QVERIFY(dialog.computedStatement().endsWith(QLatin1String("CG 0 0 0.1")));
}

void DialogsTest::negativeDensityShowsTheSolversError()
{
    Fixture fx;
    InertiaDialog dialog(fx.bundle);
    QTableWidget* t = dialog.solidsTable();
    edit(t, 0, InertiaDialog::ValueColumn, QStringLiteral("-1000"));
    QVERIFY(!dialog.result());
    QVERIFY2(dialog.errorText().contains(QLatin1String("RHO")), qPrintable(dialog.errorText()));
    QVERIFY(dialog.errorText().contains(QLatin1String("positive")));
    QVERIFY(!dialog.replaceButton()->isEnabled());
    QVERIFY(dialog.computedStatement().isEmpty());
    QCOMPARE(t->item(0, InertiaDialog::ValueColumn)->background().color(), QColor(255, 220, 220));
    // fixed again
    edit(t, 0, InertiaDialog::ValueColumn, QStringLiteral("1000"));
    QVERIFY(dialog.result());
    QVERIFY(dialog.errorText().isEmpty());
    QVERIFY(dialog.replaceButton()->isEnabled());
}

void DialogsTest::badNumbersAndDimensionsShowErrors()
{
    Fixture fx;
    InertiaDialog dialog(fx.bundle);
    QTableWidget* t = dialog.solidsTable();
    edit(t, 0, InertiaDialog::DimsColumn, QStringLiteral("0.2 0,4 0.6"));
    QVERIFY(!dialog.result());
    QVERIFY2(dialog.errorText().contains(QLatin1String("0.4")), qPrintable(dialog.errorText()));  // "use '.' …: 0.4"
    edit(t, 0, InertiaDialog::DimsColumn, QStringLiteral("0.2 -0.4 0.6"));
    QVERIFY(!dialog.result());
    QVERIFY2(dialog.errorText().contains(QLatin1String("positive")), qPrintable(dialog.errorText()));
    edit(t, 0, InertiaDialog::DimsColumn, QStringLiteral("0.2 0.4"));
    QVERIFY(!dialog.result());
    QVERIFY(!dialog.errorText().isEmpty());
    edit(t, 0, InertiaDialog::ShapeColumn, QStringLiteral("BALL"));
    QVERIFY(!dialog.result());
    QVERIFY(dialog.errorText().contains(QLatin1String("BALL")));
    edit(t, 0, InertiaDialog::ShapeColumn, QStringLiteral("CYL"));  // CYL R L: 0.2 0.4
    QVERIFY2(dialog.result(), qPrintable(dialog.errorText()));
    QVERIFY(near(dialog.result()->mass, 1000 * std::numbers::pi * 0.04 * 0.4));
}

void DialogsTest::tableRoundTripMatchesTheCalculator()
{
    // body 2's solids (CYL with AXIS and ROT, PRISM with MASS, TUBE), unedited, give
    // exactly what the solver's calculator gives for the file
    Fixture fx;
    InertiaDialog dialog(fx.bundle);
    QVERIFY(dialog.setBody(2));
    QCOMPARE(dialog.solidsTable()->rowCount(), 3);
    QVERIFY2(dialog.result(), qPrintable(dialog.errorText()));
    solver::Diagnostics diags;
    const auto expected = solver::bodyMassProperties(fx.bundle->spec(), 2, diags);
    QVERIFY(expected);
    QVERIFY(near(dialog.result()->mass, expected->mass));
    QVERIFY((dialog.result()->com - expected->com).norm() < 1e-14);
    QVERIFY((dialog.result()->inertia - expected->inertia).norm() < 1e-12 * expected->inertia.norm());
    QVERIFY(std::abs(dialog.result()->inertia(0, 1)) > 1e-6);  // ROT 30° gives products
    QCOMPARE(dialog.fileBLine(), QStringLiteral("B 2 10 0.1 0.1 0.1 CG 0 0 0.1 NAME \"arm\""));
    QVERIFY(dialog.computedBLine().endsWith(QLatin1String(" NAME \"arm\"")));
    QVERIFY(!dialog.setBody(0));
    QVERIFY(!dialog.setBody(7));
}

void DialogsTest::replaceButtonEmitsTheBLine()
{
    Fixture fx;
    InertiaDialog dialog(fx.bundle);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QSignalSpy spy(&dialog, &InertiaDialog::bLineReady);
    QTest::mouseClick(dialog.replaceButton(), Qt::LeftButton);
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).toInt(), 1);
    QCOMPARE(spy.at(0).at(1).toString(), dialog.computedBLine());
    QCOMPARE(spy.at(0).at(2).toInt(), 3);

    // what the main window does with it: the editor's text gets the new line, and the
    // model still loads with the computed body
    QPlainTextEdit editor;
    editor.setPlainText(QString::fromUtf8(kModel));
    InertiaDialog::applyBLine(&editor, spy.at(0).at(2).toInt(), spy.at(0).at(1).toString());
    solver::Diagnostics diags;
    auto again = studio::makeBundle(editor.toPlainText(), fx.path, diags);
    QVERIFY(again);
    QVERIFY(near(again->spec().body(1)->mass, 48));
    QCOMPARE(again->spec().body(1)->name, std::string("block"));
    QCOMPARE(editor.toPlainText().split(QLatin1Char('\n'))[2], dialog.computedBLine());
}

void DialogsTest::applyBLineIsOneUndoStep()
{
    QPlainTextEdit editor;
    const QString original = QString::fromUtf8(kModel);
    editor.setPlainText(original);
    editor.document()->clearUndoRedoStacks();
    const QString line = QStringLiteral("B 1 48 2.08 1.6 0.8 0 0 0 CG 0 0 0 NAME \"block\"");
    InertiaDialog::applyBLine(&editor, 3, line);
    const QStringList lines = editor.toPlainText().split(QLatin1Char('\n'));
    QCOMPARE(lines[2], line);
    QCOMPARE(lines[1], QStringLiteral("GRAVITY 0 0 -9.81"));
    QCOMPARE(lines[3], QStringLiteral("B 2 10 0.1 0.1 0.1 CG 0 0 0.1 NAME \"arm\""));
    QCOMPARE(lines.size(), original.split(QLatin1Char('\n')).size());
    editor.undo();  // one undo restores all
    QCOMPARE(editor.toPlainText(), original);
    QVERIFY(!editor.document()->isUndoAvailable());
}

void DialogsTest::applyBLineInsertsAfterTheLastBStatement()
{
    QPlainTextEdit editor;
    const QString original = QStringLiteral("B 1 1 1 1 1\nB 2 1 1 1 1\nC 1\nB1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0\n");
    editor.setPlainText(original);
    editor.document()->clearUndoRedoStacks();
    InertiaDialog::applyBLine(&editor, -1, QStringLiteral("B 3 2 0.1 0.1 0.1"));
    QCOMPARE(editor.toPlainText(), QStringLiteral("B 1 1 1 1 1\nB 2 1 1 1 1\nB 3 2 0.1 0.1 0.1\nC 1\nB1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0\n"));
    editor.undo();
    QCOMPARE(editor.toPlainText(), original);
    QVERIFY(!editor.document()->isUndoAvailable());
    // the text moved since the model was loaded: line 1 is no longer B 2's
    editor.setPlainText(QStringLiteral("// new comment\nB 1 1 1 1 1\nB 2 1 1 1 1  // two\n"));
    editor.document()->clearUndoRedoStacks();
    InertiaDialog::applyBLine(&editor, 2, QStringLiteral("B 2 5 0.5 0.5 0.5  // two"));
    QCOMPARE(editor.toPlainText(), QStringLiteral("// new comment\nB 1 1 1 1 1\nB 2 5 0.5 0.5 0.5  // two\n"));
    editor.undo();
    QCOMPARE(editor.toPlainText(), QStringLiteral("// new comment\nB 1 1 1 1 1\nB 2 1 1 1 1  // two\n"));
    // ... or B 12 is not B 1
    editor.setPlainText(QStringLiteral("B 12 1 1 1 1\nB 1 1 1 1 1"));
    InertiaDialog::applyBLine(&editor, 1, QStringLiteral("B 1 2 2 2 2"));
    QCOMPARE(editor.toPlainText(), QStringLiteral("B 12 1 1 1 1\nB 1 2 2 2 2"));
    // no B statement at all: at the end
    editor.setPlainText(QStringLiteral("GRAVITY 0 0 -9.81"));
    InertiaDialog::applyBLine(&editor, -1, QStringLiteral("B 1 2 0.1 0.1 0.1"));
    QCOMPARE(editor.toPlainText(), QStringLiteral("GRAVITY 0 0 -9.81\nB 1 2 0.1 0.1 0.1"));
}

void DialogsTest::bStatementKeepsNameAndComment()
{
    using studio::bstatement::replaceInLine;
    // the comment stays at its column
    const QString boom = QStringLiteral("  B 2 306.0 73.4 15.2 73.4 NAME \"pluma\"          // C: boom");
    const QString replaced = replaceInLine(boom, QStringLiteral("B 2 1 2 3 4"));
    QVERIFY(replaced.startsWith(QLatin1String("  B 2 1 2 3 4 NAME \"pluma\"   ")));
    QCOMPARE(replaced.indexOf(QLatin1String("// C: boom")), boom.indexOf(QLatin1String("// C: boom")));
    QVERIFY(replaced.endsWith(QLatin1String(" // C: boom")));
    // too long for the old column: two spaces before the comment
    QCOMPARE(replaceInLine(QStringLiteral("B 2 1 1 1 1  // c"), QStringLiteral("B 2 1 2 3 4 0 0 0 CG 0 0 0")),
             QStringLiteral("B 2 1 2 3 4 0 0 0 CG 0 0 0  // c"));
    QCOMPARE(replaceInLine(QStringLiteral("B 5 1 1 1 1 NAME \"a \\\"b\\\"\" # x"), QStringLiteral("B 5 2 2 2 2 0 0 0 CG 0 0 0")),
             QStringLiteral("B 5 2 2 2 2 0 0 0 CG 0 0 0 NAME \"a \\\"b\\\"\" # x"));  // a one-blank gap stays
    QCOMPARE(replaceInLine(QStringLiteral("B 1"), QStringLiteral("B 1 2 3 4 5")), QStringLiteral("B 1 2 3 4 5"));
    QVERIFY(replaceInLine(QStringLiteral("B1 0 P1 0 0 0"), QStringLiteral("B 1")).isEmpty());
    QVERIFY(replaceInLine(QStringLiteral("B 1 NAME \"open"), QStringLiteral("B 1")).isEmpty());
    solver::MassProperties p;
    p.mass = 306;
    p.inertia = Eigen::Vector3d(81.2734, 15.1498, 81.2734).asDiagonal();
    p.inertia(0, 1) = p.inertia(1, 0) = 1e-17;
    p.com = Eigen::Vector3d(0, 1e-18, 0.25);
    QCOMPARE(studio::bstatement::format(2, p), QStringLiteral("B 2 306 81.2734 15.1498 81.2734 0 0 0 CG 0 0 0.25"));
}

void DialogsTest::screenshot()
{
    Fixture fx;
    InertiaDialog dialog(fx.bundle);
    dialog.setBody(2);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    const QString dir = QStringLiteral(PADROB_SCREENSHOT_DIR);
    QVERIFY(QDir().mkpath(dir));
    QVERIFY(dialog.grab().save(dir + QStringLiteral("/inertia_dialog.png")));
    dialog.setBody(1);
    edit(dialog.solidsTable(), 0, InertiaDialog::ValueColumn, QStringLiteral("-1000"));
    QVERIFY(dialog.grab().save(dir + QStringLiteral("/inertia_dialog_error.png")));
}

// An open dialog changes language: its labels, headers and results (numbers with a
// decimal comma in Spanish), while what is model text — the table's dimensions and
// values, the B lines — keeps '.'; the edits in the table stay.
void DialogsTest::spanishAtRunTime()
{
    Fixture fx;
    InertiaDialog dialog(fx.bundle);
    dialog.setBody(2);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QTableWidget* t = dialog.solidsTable();
    edit(t, 0, InertiaDialog::ValueColumn, QStringLiteral("7800.5"));  // an edit that must survive
    QVERIFY(dialog.result());
    const QString statement = dialog.computedStatement();
    const QString bLine = dialog.computedBLine();
    const QString dir = QStringLiteral(PADROB_SCREENSHOT_DIR);
    QVERIFY(QDir().mkpath(dir));
    QVERIFY(dialog.grab().save(dir + QStringLiteral("/inertia_dialog_en.png")));
    auto massLabel = [&] {
        for (QLabel* l : dialog.findChildren<QLabel*>())
            if (l->text().endsWith(QLatin1String(" kg")) && l->textInteractionFlags() & Qt::TextSelectableByMouse) return l->text();
        return QString();
    };
    QVERIFY2(massLabel().contains('.') && !massLabel().contains(','), qPrintable(massLabel()));

    QVERIFY(i18n::install("es"));
    QTRY_COMPARE(dialog.windowTitle(), QStringLiteral("Calculadora de inercia"));
    QCOMPARE(t->horizontalHeaderItem(InertiaDialog::ShapeColumn)->text(), QStringLiteral("Forma"));
    QCOMPARE(dialog.bodyCombo()->currentText(), QStringLiteral("B 2  arm (sólidos: 3)"));
    QVERIFY2(massLabel().contains(',') && !massLabel().contains('.'), qPrintable(massLabel()));
    // model text keeps '.': the table and the B lines are as they were
    QCOMPARE(t->item(0, InertiaDialog::ValueColumn)->text(), QStringLiteral("7800.5"));
    QCOMPARE(t->item(0, InertiaDialog::DimsColumn)->text(), QStringLiteral("0.05 0.6"));
    QCOMPARE(dialog.computedStatement(), statement);
    QCOMPARE(dialog.computedBLine(), bLine);
    QVERIFY(!statement.contains(','));
    QVERIFY(!t->item(0, InertiaDialog::MassColumn)->text().contains('.'));
    QTest::qWait(100);  // (the layout, for the longer labels)
    QVERIFY(dialog.grab().save(dir + QStringLiteral("/inertia_dialog_es.png")));
    // an error, in Spanish
    edit(t, 0, InertiaDialog::ValueColumn, QStringLiteral("-1000"));
    QVERIFY(!dialog.result());
    QVERIFY2(dialog.errorText().startsWith(QStringLiteral("Error: ")), qPrintable(dialog.errorText()));
    QTest::qWait(100);
    QVERIFY(dialog.grab().save(dir + QStringLiteral("/inertia_dialog_error_es.png")));

    QVERIFY(i18n::install("en"));
    QTRY_COMPARE(dialog.windowTitle(), QStringLiteral("Inertia calculator"));
    QCOMPARE(t->horizontalHeaderItem(InertiaDialog::ShapeColumn)->text(), QStringLiteral("Shape"));
}

QTEST_MAIN(DialogsTest)
#include "dialogs_test.moc"
