#include "ide/studio/editor/problems_view.h"

#include "ide/studio/editor/diagnostic_text.h"

#include <QEvent>
#include <QHeaderView>
#include <QSignalBlocker>

#include <algorithm>

namespace studio {

ProblemsView::ProblemsView(QWidget* parent) : QTreeWidget(parent)
{
    setColumnCount(3);
    retranslate();
    setRootIsDecorated(false);
    setUniformRowHeights(true);
    setAlternatingRowColors(true);
    setSelectionMode(QAbstractItemView::SingleSelection);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setTextElideMode(Qt::ElideRight);
    header()->setStretchLastSection(true);
    header()->setSectionResizeMode(LocationColumn, QHeaderView::ResizeToContents);
    setColumnWidth(MessageColumn, 420);
    connect(this, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* item) { activate(item); });
    connect(this, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) { activate(item); });
}

void ProblemsView::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        // the messages and hints in the new language, the same row current
        const int current = currentItem() ? indexOfTopLevelItem(currentItem()) : -1;
        fill();
        if (current >= 0 && current < topLevelItemCount()) {
            const QSignalBlocker block(this);
            setCurrentItem(topLevelItem(current));
        }
    }
    QTreeWidget::changeEvent(event);
}

void ProblemsView::retranslate() { setHeaderLabels({tr("Line:col"), tr("Message"), tr("Hint")}); }

void ProblemsView::setDiagnostics(const std::vector<solver::Diagnostic>& diagnostics)
{
    m_diagnostics = diagnostics;
    fill();
}

void ProblemsView::fill()
{
    std::vector<const solver::Diagnostic*> sorted;
    sorted.reserve(m_diagnostics.size());
    for (const solver::Diagnostic& d : m_diagnostics) sorted.push_back(&d);
    std::stable_sort(sorted.begin(), sorted.end(), [](const solver::Diagnostic* a, const solver::Diagnostic* b) {
        if (a->pos.line != b->pos.line) return a->pos.line < b->pos.line;
        return a->pos.column < b->pos.column;
    });

    setUpdatesEnabled(false);
    clear();
    QList<QTreeWidgetItem*> items;
    items.reserve(qsizetype(sorted.size()));
    for (const solver::Diagnostic* d : sorted) {
        auto* item = new QTreeWidgetItem;
        const QString message = diagnosticMessage(*d);
        const QString hint = diagnosticHint(*d);
        item->setIcon(LocationColumn, severityIcon(d->severity));
        item->setText(LocationColumn, d->pos.valid() ? diagnosticLocation(*d) : QStringLiteral("—"));
        item->setText(MessageColumn, message);
        item->setText(HintColumn, hint);
        item->setForeground(LocationColumn, severityColor(d->severity));
        const QString tip = diagnosticToolTip(*d);
        for (int c = 0; c < 3; ++c) item->setToolTip(c, tip);
        item->setData(LocationColumn, LineRole, d->pos.line);
        item->setData(LocationColumn, ColumnRole, d->pos.column);
        item->setData(LocationColumn, CodeRole, QString::fromStdString(d->code));
        item->setData(LocationColumn, Qt::AccessibleTextRole,
                      tr("%1 at %2: %3").arg(severityText(d->severity), diagnosticLocation(*d), message));
        items.append(item);
    }
    addTopLevelItems(items);
    setUpdatesEnabled(true);
}

void ProblemsView::activate(QTreeWidgetItem* item)
{
    if (!item) return;
    const int line = item->data(LocationColumn, LineRole).toInt();
    const int column = item->data(LocationColumn, ColumnRole).toInt();
    if (line > 0) emit problemActivated(line, column);
}

}  // namespace studio
