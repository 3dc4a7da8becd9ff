#pragma once
// InertiaDialog: the inertia calculator (docs/model-language.md "Inertia of solids").
//
// Pick a body; its solids — the graphics (G) of that body with MASS or RHO — are
// listed in an editable table (shape, dimensions, POS, AXIS, ROT, density or mass).
// Every edit recomputes at once, through the solver's own parser, checks and
// calculator (solver/inertia/solid_inertia.h), the body's mass, centre of mass,
// inertia tensor about it and principal moments; a bad value shows the solver's
// diagnostic instead (nothing is computed then). The computed B line is shown beside
// the file's current one, and "Replace B line in editor" hands it over with
// bLineReady(); the main window puts it into the editor as one undo step (applyBLine
// does exactly that). The edits in the table are for the calculation only: the G
// lines themselves are not written back (the dialog says so).

#include "ide/studio/model/model_bundle.h"
#include "solver/inertia/solid_inertia.h"
#include "solver/spec/model_spec.h"

#include <QDialog>
#include <QString>

#include <memory>
#include <optional>

class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QTableWidget;

namespace studio {

class InertiaDialog : public QDialog {
    Q_OBJECT
public:
    /// The table's columns.
    enum Column { IdColumn, ShapeColumn, DimsColumn, PosColumn, AxisColumn, RotColumn, KindColumn, ValueColumn, MassColumn, ColumnCount };

    /// For a loaded model (its file's B lines are read from the file, or from the
    /// text given with setSourceText()).
    explicit InertiaDialog(std::shared_ptr<const ModelBundle> bundle, QWidget* parent = nullptr);
    /// For a spec (e.g. one with errors elsewhere) and the path of its file ("" if none).
    InertiaDialog(const solver::ModelSpec& spec, const QString& filePath, QWidget* parent = nullptr);
    ~InertiaDialog() override;

    /// The model's current text (the editor's), where the B lines are read; by default
    /// the file on disk.
    void setSourceText(const QString& text);

    /// Shows body `id`; false when it is not in the list (ground, unknown).
    bool setBody(int id);
    int bodyId() const;

    /// The computed mass properties (body axes, about the centre of mass); nullopt
    /// while the solids have errors or there are none.
    const std::optional<solver::MassProperties>& result() const { return m_result; }
    /// The diagnostics shown instead of a result ("" when none).
    QString errorText() const;
    /// "B id m Ixx Iyy Izz Ixy Iyz Ixz CG x y z" ("" without a result).
    QString computedStatement() const { return m_statement; }
    /// The whole line that would replace the body's B line (its NAME and comment kept).
    QString computedBLine() const { return m_bLine; }
    /// The body's B line as it is in the file ("" when unknown).
    QString fileBLine() const { return m_fileLine; }
    /// Line (1-based) of the body's B statement, or −1.
    int bStatementLine() const;

    QComboBox* bodyCombo() const { return m_body; }
    QTableWidget* solidsTable() const { return m_table; }
    QPushButton* replaceButton() const { return m_replace; }

    /// Replaces line `line` (1-based) of `editor` by `text`, or, with line −1, inserts
    /// `text` as a new line after the last B statement (at the end without one). When
    /// `line` no longer holds the B statement of `text`'s body (the text changed since
    /// the model was loaded), that body's B statement is looked for elsewhere, and
    /// inserted when there is none. One QTextCursor edit block: a single undo step.
    static void applyBLine(QPlainTextEdit* editor, int line, const QString& text);

signals:
    /// "Replace B line in editor": the body, its new line, and the line of its current
    /// B statement (−1: none, insert one).
    void bLineReady(int bodyId, const QString& bLine, int lineOfExistingBStatement);

protected:
    /// A language change: every label, header and result again (the table's edits stay).
    void changeEvent(QEvent* event) override;

private:
    static constexpr int LineRole = Qt::UserRole + 1;  ///< of the Graphic column: the G statement's line
    void build();
    void retranslateStatic();
    void retranslateRow(int row);
    QString bodyText(int id) const;
    void fillBodies();
    void loadSolids();
    void recompute();
    void showResult();
    QString sourceLine(int line) const;
    /// The line of `body`'s B statement in the source text now (-1: none).
    int bodyLine(const solver::BodySpec& body) const;

    std::shared_ptr<const ModelBundle> m_bundle;
    std::shared_ptr<const solver::ModelSpec> m_spec;
    QString m_filePath;
    QString m_modelDir;
    QStringList m_sourceLines;
    bool m_haveSource = false;
    bool m_loading = false;

    std::optional<solver::MassProperties> m_result;
    QString m_statement, m_bLine, m_fileLine;

    QLabel* m_bodyLabel = nullptr;
    QLabel* m_note = nullptr;
    QGroupBox* m_results = nullptr;
    QGroupBox* m_lines = nullptr;
    QLabel* m_massLabel = nullptr;
    QLabel* m_comLabel = nullptr;
    QLabel* m_tensorLabel = nullptr;
    QLabel* m_principalLabel = nullptr;
    QLabel* m_differenceLabel = nullptr;
    QLabel* m_fileBLabel = nullptr;
    QLabel* m_computedBLabel = nullptr;
    QComboBox* m_body = nullptr;
    QTableWidget* m_table = nullptr;
    QLabel* m_errors = nullptr;
    QLabel* m_mass = nullptr;
    QLabel* m_com = nullptr;
    QTableWidget* m_tensor = nullptr;
    QLabel* m_principal = nullptr;
    QLabel* m_difference = nullptr;
    QLineEdit* m_fileB = nullptr;
    QLineEdit* m_computedB = nullptr;
    QPushButton* m_replace = nullptr;
};

}  // namespace studio
