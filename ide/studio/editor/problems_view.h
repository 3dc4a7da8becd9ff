#pragma once
// ProblemsView: the list of a model's diagnostics, top to bottom — severity icon
// and colour, "line:col", message and hint. Clicking or activating (double-click,
// Enter) a row emits problemActivated(line, column), which the editor panel turns
// into CodeEditor::goToLine.

#include "solver/core/diagnostic.h"

#include <QTreeWidget>

#include <vector>

namespace studio {

class ProblemsView : public QTreeWidget {
    Q_OBJECT
public:
    enum Column { LocationColumn, MessageColumn, HintColumn };
    /// Item data roles: the diagnostic's 1-based line and column (0 = no position).
    static constexpr int LineRole = Qt::UserRole;
    static constexpr int ColumnRole = Qt::UserRole + 1;
    static constexpr int CodeRole = Qt::UserRole + 2;

    explicit ProblemsView(QWidget* parent = nullptr);

    /// Replaces the list (sorted by position; those without one first).
    void setDiagnostics(const std::vector<solver::Diagnostic>& diagnostics);
    int problemCount() const { return topLevelItemCount(); }

signals:
    /// A problem was clicked or activated; line/column are 1-based (0: no position).
    void problemActivated(int line, int column);

protected:
    /// A language change: the headers and every problem again, in the new language.
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void fill();
    void activate(QTreeWidgetItem* item);

    std::vector<solver::Diagnostic> m_diagnostics;  // as given (shown sorted)
};

}  // namespace studio
