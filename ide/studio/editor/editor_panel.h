#pragma once
// EditorPanel: the Model workspace's editor — a CodeEditor over a ModelDocument,
// a bar with the check status and the Apply button, and the ProblemsView.
//
// Live check: every change of the text (re)starts a debounce timer (checkDelay(),
// 400 ms); when it fires the text is loaded and compiled by studio::makeBundle on
// a worker thread (ModelChecker). The result, if the text has not changed since,
// becomes the underlines, the problem list and diagnosticsChanged(errors, warnings).
//
// Apply: applied(bundle) is emitted only for text without errors — the bundle of
// the current text. While the text has errors the button is disabled and apply()
// explains instead; nothing is emitted and lastGood() stays the last applied
// model. Applying text not yet checked waits for its check.
//
// Not applied: after an apply, any text other than the applied one (an edit, a file
// opened or made with New that is not applied yet) makes hasUnappliedChanges() true
// and emits unappliedChanged(true); applying, or the text coming back to the applied
// one (undo, revertToApplied()), makes it false. The main window says so over the 3D
// view, the tree and the plots, which show the applied model.
//
// Changed on disk: when the file changed on disk while the text has unsaved edits,
// offerReload() shows a bar over the editor ("… changed on disk", Reload, Keep my
// text) instead of replacing the edits; Reload emits reloadRequested().
//
// Documents: newModel/open/save/saveAs/reload and the modified flag are the
// ModelDocument's (see there: QSaveFile, the file watcher, recovery copies); the
// main window asks before closing a modified model (isModified()).

#include "ide/studio/editor/code_editor.h"
#include "ide/studio/editor/model_document.h"
#include "ide/studio/editor/problems_view.h"
#include "ide/studio/model/model_bundle.h"
#include "solver/core/diagnostic.h"

#include <QWidget>

#include <memory>
#include <vector>

class QLabel;
class QPushButton;
class QSplitter;
class QTimer;

namespace studio {

class ModelChecker;

class EditorPanel : public QWidget {
    Q_OBJECT
public:
    /// Default debounce between the last keystroke and the check [ms].
    static constexpr int kDefaultCheckDelayMs = 400;

    explicit EditorPanel(QWidget* parent = nullptr);
    ~EditorPanel() override;

    CodeEditor* editor() const { return m_editor; }
    ProblemsView* problemsView() const { return m_problems; }
    ModelDocument* document() const { return m_document; }
    QPushButton* applyButton() const { return m_apply; }

    // ---- text and file ---------------------------------------------------------
    QString text() const;
    /// Replaces the whole text as one undoable edit.
    void setText(const QString& text);
    void newModel(const QString& text = {});
    bool open(const QString& path, QString* errorMessage = nullptr);
    bool save(QString* errorMessage = nullptr);
    bool saveAs(const QString& path, QString* errorMessage = nullptr);
    bool reload(QString* errorMessage = nullptr);
    // ---- recovery copies (see ModelDocument) ------------------------------------------
    using Recovery = RecoveryEntry;
    /// Recovery copies left by a session that ended without saving (a crash), newest
    /// first: the main window offers them at start.
    static QList<Recovery> recoveryFiles();
    /// Deletes a recovery copy the modeler does not want.
    static bool discardRecovery(const Recovery& recovery);
    /// Restores a recovery copy into the editor: its text, modified, with the
    /// original file path (save writes it there).
    bool restoreRecovery(const Recovery& recovery, QString* errorMessage = nullptr);
    /// Deletes this editor's own recovery copy (closing without saving, by choice).
    void discardOwnRecovery();
    QString filePath() const;
    bool isModified() const;
    /// For the window title: "pendulum.pad" or "Untitled".
    QString displayName() const;

    // ---- checking ----------------------------------------------------------------
    void setCheckDelay(int ms);
    int checkDelay() const;
    /// Starts the check of the current text now (no debounce).
    void checkNow();
    /// The current text has not been checked yet (waiting or running).
    bool isChecking() const;
    /// Counts and list of the last check of the current text.
    int errorCount() const { return m_errors; }
    int warningCount() const { return m_warnings; }
    const std::vector<solver::Diagnostic>& diagnostics() const { return m_diagnostics; }
    /// The bundle of the current text when it checked without errors, else null.
    std::shared_ptr<const ModelBundle> checkedBundle() const;
    /// The model last applied (null before the first apply).
    std::shared_ptr<const ModelBundle> lastGood() const { return m_lastGood; }
    /// The status line shown next to the Apply button.
    QString statusText() const;
    /// "2 errors, 1 warning", "1 warning", "No problems" in the current language.
    static QString problemCounts(int errors, int warnings);

    // ---- not applied, changed on disk ------------------------------------------------
    /// A model was applied and the text is another one (see above).
    bool hasUnappliedChanges() const { return m_unapplied; }
    /// The text of the model last applied ("" before the first apply).
    QString appliedText() const { return m_appliedText; }
    /// Back to the applied text, as one undoable edit.
    void revertToApplied();
    /// The bar over the editor that offers to reload `path`, changed on disk (the
    /// unsaved edits stay until Reload is pressed); hidden by Reload, Keep my text,
    /// another file or a save.
    void offerReload(const QString& path);
    /// The bar above is shown.
    bool isOfferingReload() const;

public slots:
    /// Emits applied() for the current text if it has no errors (after its check
    /// if it is not checked yet); otherwise says why and emits nothing.
    void apply();
    void undo();
    void redo();
    /// Moves the editor's cursor to `line`:`column` (1-based) and focuses it.
    void goToLine(int line, int column = 1);

signals:
    /// After every check of the current text.
    void diagnosticsChanged(int errors, int warnings);
    /// A model without errors was applied.
    void applied(std::shared_ptr<const studio::ModelBundle> bundle);
    void modificationChanged(bool modified);
    void filePathChanged(const QString& path);
    /// Another program changed or deleted the open file: offer reload().
    void fileChangedOnDisk(const QString& path, bool deleted);
    /// hasUnappliedChanges() changed.
    void unappliedChanged(bool unapplied);
    /// Reload was pressed on the bar of offerReload().
    void reloadRequested();

protected:
    /// A language change: the button and the status line again.
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void textChanged();
    void onChecked(quint64 revision, std::shared_ptr<const ModelBundle> bundle, const solver::Diagnostics& diags);
    void updateStatus();
    void setStatus(const QString& text, const QColor& color);
    void setUnapplied(bool unapplied);
    void hideReloadBar();

    CodeEditor* m_editor = nullptr;
    ProblemsView* m_problems = nullptr;
    ModelDocument* m_document = nullptr;
    ModelChecker* m_checker = nullptr;
    QPushButton* m_apply = nullptr;
    QLabel* m_status = nullptr;
    QSplitter* m_splitter = nullptr;
    QTimer* m_debounce = nullptr;
    QWidget* m_reloadBar = nullptr;
    QLabel* m_reloadText = nullptr;
    QPushButton* m_reload = nullptr;
    QPushButton* m_keep = nullptr;
    QString m_reloadPath;  // the file the bar is about

    quint64 m_revision = 1;         // counts text changes
    quint64 m_checkedRevision = 0;  // the revision of the last result shown
    quint64 m_requestedRevision = 0;
    bool m_applyPending = false;
    int m_errors = 0, m_warnings = 0;
    std::vector<solver::Diagnostic> m_diagnostics;
    std::shared_ptr<const ModelBundle> m_checked;
    std::shared_ptr<const ModelBundle> m_lastGood;
    QString m_appliedText;
    quint64 m_appliedRevision = 0;  // the revision applied last (or found equal to its text)
    bool m_unapplied = false;
    int m_refusedErrors = -1;  // the last apply() did nothing: the errors it found (0: not compiled), −1: not refused
};

}  // namespace studio
