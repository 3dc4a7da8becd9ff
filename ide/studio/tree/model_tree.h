#pragma once
// ModelTree: the model's structure as a tree (DESIGN "model tree with the DOF
// classification"), for the model's ModelBundle:
//
//   Bodies          id, name, mass (the ground first)
//   Joints          id, name, type (revolute / pivoted actuator / prismatic),
//                   role (independent / dependent / loop closure), limits with
//                   units, drive summary
//   Chains          the joints of each serial chain, from ground outwards
//   Loop closures   the joints that close loops (constraints, not coordinates)
//   Coordinates     independent (the degrees of freedom) and dependent joints,
//                   with their initial coordinates
//
// Selecting an item emits bodySelected / jointSelected with the compiled model's
// tree index (−1 for the ground or a loop-closing joint) and sourceSelected with
// the line of the statement, so the editor can jump there. selectBody() and
// selectJoint() follow a selection made elsewhere (viewport) without emitting.

#include "ide/studio/model/model_bundle.h"

#include <QTreeWidget>

#include <memory>

namespace studio {

class ModelTree : public QTreeWidget {
    Q_OBJECT
public:
    /// What an item stands for (ItemKindRole).
    enum class ItemKind { Group, Body, Joint, Chain, Info };
    /// Data roles of column 0.
    enum Role {
        ItemKindRole = Qt::UserRole + 1,  ///< ItemKind as int
        IdRole,                           ///< modeler's id of the body or joint
        TreeIndexRole,                    ///< compiled model's tree index; −1 ground / cut joint
        LineRole,                         ///< source line of the statement; 0 when not written
    };
    /// The columns.
    enum Column { ElementColumn, TypeColumn, RoleColumn, DetailsColumn, DriveColumn, ColumnCount };
    /// The top-level groups, in order.
    enum class Group { Bodies, Joints, Chains, LoopClosures, Coordinates };

    explicit ModelTree(QWidget* parent = nullptr);

    /// Shows `bundle` (nullptr: empty). Keeps the selected body or joint when the new
    /// model has it.
    void setBundle(std::shared_ptr<const ModelBundle> bundle);
    std::shared_ptr<const ModelBundle> bundle() const { return m_bundle; }

    /// Selects the body with tree index `treeIndex` (−1: the ground) without emitting.
    void selectBody(int treeIndex);
    /// Selects the joint with tree index `treeIndex` (its item in "Joints") without emitting.
    void selectJoint(int treeIndex);

    /// The top-level item of a group (nullptr without a model).
    QTreeWidgetItem* groupItem(Group group) const;
    /// The item of body `id` (0: the ground) or joint `id` in "Bodies" / "Joints".
    QTreeWidgetItem* bodyItem(int id) const;
    QTreeWidgetItem* jointItem(int id) const;

signals:
    void bodySelected(int treeIndex);
    void jointSelected(int treeIndex);
    /// The line (1-based) of the selected element's statement.
    void sourceSelected(int line);

protected:
    /// A language change: the headers and every item again.
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void rebuild();
    void onCurrentItemChanged(QTreeWidgetItem* current);
    void emitFor(QTreeWidgetItem* item);
    QTreeWidgetItem* addGroup(Group group, const QString& title);
    QTreeWidgetItem* addJoint(QTreeWidgetItem* parent, int specIndex);
    QTreeWidgetItem* findItem(ItemKind kind, int role, int value) const;

    std::shared_ptr<const ModelBundle> m_bundle;
    QTreeWidgetItem* m_groups[static_cast<int>(Group::Coordinates) + 1] = {};
    bool m_syncing = false;  // selection set from outside: no signals
};

}  // namespace studio
