#include "ide/studio/editor/editor_panel.h"

#include "ide/studio/editor/code_editor.h"
#include "ide/studio/editor/diagnostic_text.h"
#include "ide/studio/editor/model_checker.h"
#include "ide/studio/editor/problems_view.h"

#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QStyle>
#include <QTextDocument>
#include <QTimer>
#include <QVBoxLayout>

namespace studio {

EditorPanel::EditorPanel(QWidget* parent) : QWidget(parent)
{
    m_editor = new CodeEditor(this);
    m_document = new ModelDocument(m_editor->document(), this);
    m_problems = new ProblemsView(this);
    m_checker = new ModelChecker(this);

    m_status = new QLabel(this);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // (no shortcut here: the main window's Apply Model action has Ctrl+Return)
    m_apply = new QPushButton(style()->standardIcon(QStyle::SP_DialogApplyButton), QString(), this);

    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(4, 2, 4, 2);
    bar->addWidget(m_status, 1);
    bar->addWidget(m_apply);
    auto* bottom = new QWidget(this);
    auto* bottomLayout = new QVBoxLayout(bottom);
    bottomLayout->setContentsMargins(0, 0, 0, 0);
    bottomLayout->setSpacing(2);
    bottomLayout->addLayout(bar);
    bottomLayout->addWidget(m_problems);

    // the file changed on disk under unsaved edits (offerReload)
    m_reloadBar = new QWidget(this);
    m_reloadBar->setObjectName("ReloadBar");
    m_reloadBar->setAutoFillBackground(true);
    m_reloadBar->setStyleSheet(QStringLiteral("QWidget#ReloadBar { background: #fff3cd; color: #3d2e00; }"));
    m_reloadText = new QLabel(m_reloadBar);
    m_reloadText->setWordWrap(true);
    m_reload = new QPushButton(m_reloadBar);
    m_reload->setObjectName("ReloadButton");
    m_keep = new QPushButton(m_reloadBar);
    m_keep->setObjectName("KeepTextButton");
    auto* reloadLayout = new QHBoxLayout(m_reloadBar);
    reloadLayout->setContentsMargins(6, 4, 6, 4);
    reloadLayout->addWidget(m_reloadText, 1);
    reloadLayout->addWidget(m_reload);
    reloadLayout->addWidget(m_keep);
    m_reloadBar->hide();
    connect(m_reload, &QPushButton::clicked, this, [this] {
        hideReloadBar();
        emit reloadRequested();
    });
    connect(m_keep, &QPushButton::clicked, this, &EditorPanel::hideReloadBar);

    m_splitter = new QSplitter(Qt::Vertical, this);
    m_splitter->addWidget(m_editor);
    m_splitter->addWidget(bottom);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 1);
    m_splitter->setChildrenCollapsible(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(m_reloadBar);
    layout->addWidget(m_splitter);

    m_debounce = new QTimer(this);
    m_debounce->setSingleShot(true);
    m_debounce->setInterval(kDefaultCheckDelayMs);

    connect(m_debounce, &QTimer::timeout, this, &EditorPanel::checkNow);
    connect(m_editor->document(), &QTextDocument::contentsChange, this, [this](int, int removed, int added) {
        if (removed || added) textChanged();
    });
    connect(m_checker, &ModelChecker::finished, this, [this](const ModelChecker::Result& r) {
        onChecked(r.revision, r.bundle, r.diagnostics);
    });
    connect(m_problems, &ProblemsView::problemActivated, this, &EditorPanel::goToLine);
    connect(m_apply, &QPushButton::clicked, this, &EditorPanel::apply);
    connect(m_document, &ModelDocument::modificationChanged, this, &EditorPanel::modificationChanged);
    // underlines of the old text go before it does (thousands of live cursors slow a big replace)
    connect(m_document, &ModelDocument::aboutToReplaceText, m_editor, &CodeEditor::clearDiagnostics);
    connect(m_document, &ModelDocument::fileChangedOnDisk, this, &EditorPanel::fileChangedOnDisk);
    connect(m_document, &ModelDocument::modificationChanged, this, [this](bool modified) {
        if (!modified) hideReloadBar();  // saved (over the file on disk) or reloaded
    });
    connect(m_document, &ModelDocument::filePathChanged, this, [this](const QString& path) {
        hideReloadBar();
        // mesh paths are relative to the file: the same text may check differently
        ++m_revision;
        checkNow();
        emit filePathChanged(path);
    });

    retranslate();
    checkNow();
}

void EditorPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void EditorPanel::retranslate()
{
    m_apply->setText(tr("Apply"));
    m_apply->setToolTip(tr("Use this model in the 3D view and the simulation"));
    m_reload->setText(tr("Reload"));
    m_reload->setToolTip(tr("Read the file again (your unsaved edits stay in Undo)"));
    m_keep->setText(tr("Keep my text"));
    m_keep->setToolTip(tr("Go on with the text in the editor; saving writes it over the file"));
    if (!m_reloadPath.isEmpty())
        m_reloadText->setText(tr("“%1” changed on disk, and the editor has unsaved changes.")
                                  .arg(QFileInfo(m_reloadPath).fileName()));
    updateStatus();
}

EditorPanel::~EditorPanel()
{
    delete m_checker;  // stops its thread before the rest goes
    m_checker = nullptr;
}

// ---- text and file ------------------------------------------------------------------

QString EditorPanel::text() const { return m_document->text(); }

void EditorPanel::setText(const QString& text) { m_document->setText(text); }

void EditorPanel::newModel(const QString& text)
{
    m_document->newModel(text);
    checkNow();
}

bool EditorPanel::open(const QString& path, QString* errorMessage)
{
    if (!m_document->open(path, errorMessage)) return false;
    checkNow();
    return true;
}

bool EditorPanel::save(QString* errorMessage) { return m_document->save(errorMessage); }

bool EditorPanel::saveAs(const QString& path, QString* errorMessage) { return m_document->saveAs(path, errorMessage); }

bool EditorPanel::reload(QString* errorMessage)
{
    if (!m_document->reload(errorMessage)) return false;
    checkNow();
    return true;
}

QList<EditorPanel::Recovery> EditorPanel::recoveryFiles() { return ModelDocument::recoveryEntries(); }

bool EditorPanel::discardRecovery(const Recovery& recovery) { return ModelDocument::discardRecovery(recovery); }

bool EditorPanel::restoreRecovery(const Recovery& recovery, QString* errorMessage)
{
    if (!m_document->restoreRecovery(recovery, errorMessage)) return false;
    checkNow();
    return true;
}

void EditorPanel::discardOwnRecovery() { m_document->removeRecoveryCopy(); }

QString EditorPanel::filePath() const { return m_document->filePath(); }

bool EditorPanel::isModified() const { return m_document->isModified(); }

QString EditorPanel::displayName() const { return m_document->displayName(); }

void EditorPanel::undo() { m_editor->undo(); }

void EditorPanel::redo() { m_editor->redo(); }

void EditorPanel::goToLine(int line, int column) { m_editor->goToLine(line, column); }

// ---- checking -------------------------------------------------------------------------

void EditorPanel::setCheckDelay(int ms) { m_debounce->setInterval(std::max(0, ms)); }

int EditorPanel::checkDelay() const { return m_debounce->interval(); }

bool EditorPanel::isChecking() const { return m_checkedRevision != m_revision; }

std::shared_ptr<const ModelBundle> EditorPanel::checkedBundle() const
{
    return m_checkedRevision == m_revision ? m_checked : nullptr;
}

void EditorPanel::textChanged()
{
    ++m_revision;
    setUnapplied(m_lastGood != nullptr && !m_applyPending);  // (an apply waiting for its check takes this text)
    m_refusedErrors = -1;
    m_debounce->start();
    updateStatus();
}

void EditorPanel::checkNow()
{
    m_debounce->stop();
    if (m_requestedRevision == m_revision || m_checkedRevision == m_revision) return;
    m_requestedRevision = m_revision;
    m_checker->check(m_revision, m_document->text(), m_document->filePath());
    updateStatus();
}

void EditorPanel::onChecked(quint64 revision, std::shared_ptr<const ModelBundle> bundle, const solver::Diagnostics& diags)
{
    if (revision != m_revision) return;  // the text changed meanwhile: a newer check follows
    m_checkedRevision = revision;
    m_checked = std::move(bundle);
    m_diagnostics = diags.items();
    m_errors = int(diags.errorCount());
    m_warnings = int(diags.warningCount());
    m_editor->setDiagnostics(m_diagnostics);
    m_problems->setDiagnostics(m_diagnostics);
    if (m_unapplied && m_document->text() == m_appliedText) {  // back to the applied text
        m_appliedRevision = m_revision;
        setUnapplied(false);
    }
    updateStatus();
    emit diagnosticsChanged(m_errors, m_warnings);
    if (std::exchange(m_applyPending, false)) apply();
}

// ---- apply ---------------------------------------------------------------------------------

void EditorPanel::apply()
{
    if (m_checkedRevision != m_revision) {
        m_applyPending = true;  // after the check of this text
        setUnapplied(false);    // (said again if it cannot be applied)
        checkNow();
        return;
    }
    if (!m_checked) {
        setUnapplied(m_lastGood != nullptr);
        m_refusedErrors = m_errors;
        updateStatus();
        return;
    }
    m_refusedErrors = -1;
    m_lastGood = m_checked;
    m_appliedText = m_document->text();
    m_appliedRevision = m_revision;
    setUnapplied(false);
    updateStatus();
    emit applied(m_lastGood);
}

// ---- not applied, changed on disk --------------------------------------------------------

void EditorPanel::setUnapplied(bool unapplied)
{
    if (unapplied == m_unapplied) return;
    m_unapplied = unapplied;
    emit unappliedChanged(unapplied);
}

void EditorPanel::revertToApplied()
{
    if (!m_lastGood || m_document->text() == m_appliedText) return;
    m_document->setText(m_appliedText);
    checkNow();
}

void EditorPanel::offerReload(const QString& path)
{
    m_reloadPath = path;
    retranslate();
    m_reloadBar->show();
}

bool EditorPanel::isOfferingReload() const { return !m_reloadBar->isHidden(); }

void EditorPanel::hideReloadBar()
{
    m_reloadPath.clear();
    m_reloadBar->hide();
}

// ---- status -------------------------------------------------------------------------------

QString EditorPanel::statusText() const { return m_status->text(); }

QString EditorPanel::problemCounts(int errors, int warnings)
{
    if (errors > 0 && warnings > 0)
        return tr("%1, %n warning(s)", "the %1 is \"%n error(s)\"", warnings).arg(tr("%n error(s)", nullptr, errors));
    if (errors > 0) return tr("%n error(s)", nullptr, errors);
    if (warnings > 0) return tr("%n warning(s)", nullptr, warnings);
    return tr("No problems");
}

void EditorPanel::setStatus(const QString& text, const QColor& color)
{
    m_status->setText(text);
    QPalette pal = m_status->palette();
    pal.setColor(QPalette::WindowText, color.isValid() ? color : palette().color(QPalette::WindowText));
    m_status->setPalette(pal);
}

void EditorPanel::updateStatus()
{
    const bool current = m_checkedRevision == m_revision;
    // with errors in the current text there is nothing to apply
    m_apply->setEnabled(!(current && m_errors > 0));
    if (m_refusedErrors >= 0) {
        setStatus(m_refusedErrors > 0 ? tr("Not applied: the model has %n error(s). The model applied before stays in use.",
                                           nullptr, m_refusedErrors)
                                      : tr("Not applied: the model could not be compiled."),
                  severityColor(solver::Severity::Error));
        return;
    }
    if (!current && m_requestedRevision == m_revision) {
        setStatus(tr("Checking…"), QColor());
        return;
    }
    if (m_errors == 0 && m_warnings == 0) {
        setStatus(current ? tr("No problems") : QString(), QColor());
        return;
    }
    setStatus(problemCounts(m_errors, m_warnings),
              severityColor(m_errors > 0 ? solver::Severity::Error : solver::Severity::Warning));
}

}  // namespace studio
