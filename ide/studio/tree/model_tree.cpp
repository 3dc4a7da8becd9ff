#include "ide/studio/tree/model_tree.h"

#include "ide/studio/tree/joint_text.h"

#include <QEvent>
#include <QHeaderView>
#include <QSignalBlocker>

#include <algorithm>

namespace studio {

namespace {

QString fromStd(const std::string& name) { return QString::fromStdString(name); }

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

}  // namespace

ModelTree::ModelTree(QWidget* parent) : QTreeWidget(parent)
{
    setColumnCount(ColumnCount);
    retranslate();
    setSelectionMode(QAbstractItemView::SingleSelection);
    setAlternatingRowColors(true);
    setUniformRowHeights(true);
    header()->setStretchLastSection(true);
    connect(this, &QTreeWidget::currentItemChanged, this,
            [this](QTreeWidgetItem* current, QTreeWidgetItem*) { onCurrentItemChanged(current); });
    // Enter or a double click on the selected item jumps to its statement again
    connect(this, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item, int) {
        if (!m_syncing) emitFor(item);
    });
}

void ModelTree::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        setBundle(m_bundle);  // every item's text again, in the new language (the selection stays)
    }
    QTreeWidget::changeEvent(event);
}

void ModelTree::retranslate()
{
    setHeaderLabels({tr("Element"), tr("Type"), tr("Role"), tr("Mass / limits"), tr("Drive")});
}

void ModelTree::setBundle(std::shared_ptr<const ModelBundle> bundle)
{
    // keep the selected body or joint across models that have it
    ItemKind kind = ItemKind::Group;
    int id = -1;
    if (QTreeWidgetItem* c = currentItem()) {
        kind = static_cast<ItemKind>(c->data(0, ItemKindRole).toInt());
        id = c->data(0, IdRole).toInt();
    }
    m_bundle = std::move(bundle);
    {
        const QSignalBlocker block(this);
        rebuild();
        QTreeWidgetItem* again = kind == ItemKind::Body ? bodyItem(id) : kind == ItemKind::Joint ? jointItem(id) : nullptr;
        if (again) setCurrentItem(again);
    }
}

QTreeWidgetItem* ModelTree::addGroup(Group group, const QString& title)
{
    auto* item = new QTreeWidgetItem(this, {title});
    item->setData(0, ItemKindRole, static_cast<int>(ItemKind::Group));
    QFont f = item->font(0);
    f.setBold(true);
    item->setFont(0, f);
    item->setFirstColumnSpanned(true);
    m_groups[static_cast<int>(group)] = item;
    return item;
}

QTreeWidgetItem* ModelTree::addJoint(QTreeWidgetItem* parent, int specIndex)
{
    const solver::ModelSpec& spec = m_bundle->spec();
    const solver::Topology& topo = m_bundle->topology();
    const solver::JointSpec& j = spec.joints[static_cast<std::size_t>(specIndex)];
    const bool cut = contains(topo.loopJoints, specIndex);
    QString role = cut ? tr("loop closure")
                 : contains(topo.dependent, specIndex) ? tr("dependent")
                 : contains(topo.independent, specIndex) ? tr("independent")
                                                         : QString();
    QString driveText = tr("passive");
    for (const solver::DriveSpec& d : spec.drives) {
        if (d.joint == j.id) driveText = jointtext::drive(d, j.type);
    }
    const QString element = j.name.empty() ? tr("C %1").arg(j.id) : tr("C %1  %2").arg(j.id).arg(fromStd(j.name));
    auto* item = new QTreeWidgetItem(parent, {element, jointtext::typeName(j.type), role, jointtext::limits(j), driveText});
    item->setData(0, ItemKindRole, static_cast<int>(ItemKind::Joint));
    item->setData(0, IdRole, j.id);
    item->setData(0, TreeIndexRole, cut ? -1 : m_bundle->model->jointIndex(j.id));
    item->setData(0, LineRole, j.src.pos.line);
    const auto bodyText = [&](int id) {
        const solver::BodySpec* b = spec.body(id);
        if (id == 0) return tr("ground");
        return b && !b->name.empty() ? tr("B %1 %2").arg(id).arg(fromStd(b->name)) : tr("B %1").arg(id);
    };
    // the tooltip: whole lines, each translated on its own
    QStringList tip{tr("Joint %1 (%2), line %3").arg(QString::number(j.id), jointtext::typeName(j.type), QString::number(j.src.pos.line)),
                    tr("between %1 and %2").arg(bodyText(j.side1.body), bodyText(j.side2.body)),
                    tr("limits: %1").arg(jointtext::limits(j)), tr("drive: %1").arg(driveText)};
    if (static_cast<std::size_t>(specIndex) < topo.q0.size()) {
        tip << tr("initial coordinate: %1").arg(jointtext::coordinate(j.type, topo.q0[static_cast<std::size_t>(specIndex)]));
    }
    for (int c = 0; c < ColumnCount; ++c) item->setToolTip(c, tip.join(QLatin1Char('\n')));
    return item;
}

void ModelTree::rebuild()
{
    clear();
    std::fill(std::begin(m_groups), std::end(m_groups), nullptr);
    if (!m_bundle) return;
    const solver::ModelSpec& spec = m_bundle->spec();
    const solver::Topology& topo = m_bundle->topology();
    const solver::Model& model = *m_bundle->model;

    // bodies: the ground, then the spec's bodies in file order
    int bodyCount = 0;
    for (const solver::BodySpec& b : spec.bodies) bodyCount += b.id != 0;
    QTreeWidgetItem* bodies = addGroup(Group::Bodies, tr("Bodies (%1)").arg(bodyCount));
    {
        const solver::BodySpec* ground = spec.body(0);
        const QString name = ground && !ground->name.empty() ? fromStd(ground->name) : tr("ground");
        auto* item = new QTreeWidgetItem(bodies, {tr("B 0  %1").arg(name), tr("ground"), QString(), tr("fixed")});
        item->setData(0, ItemKindRole, static_cast<int>(ItemKind::Body));
        item->setData(0, IdRole, 0);
        item->setData(0, TreeIndexRole, -1);
        item->setData(0, LineRole, ground ? ground->src.pos.line : 0);
    }
    for (const solver::BodySpec& b : spec.bodies) {
        if (b.id == 0) continue;
        const QString element = b.name.empty() ? tr("B %1").arg(b.id) : tr("B %1  %2").arg(b.id).arg(fromStd(b.name));
        auto* item = new QTreeWidgetItem(bodies, {element, tr("body"), QString(), jointtext::mass(b)});
        item->setData(0, ItemKindRole, static_cast<int>(ItemKind::Body));
        item->setData(0, IdRole, b.id);
        item->setData(0, TreeIndexRole, model.bodyIndex(b.id));
        item->setData(0, LineRole, b.src.pos.line);
        QStringList tip{tr("Body %1, line %2").arg(b.id).arg(b.src.pos.line), tr("mass: %1").arg(jointtext::mass(b))};
        if (b.hasMass) {
            tip << tr("Ixx Iyy Izz: %1 %2 %3 kg·m²")
                       .arg(jointtext::number(b.inertia.x()), jointtext::number(b.inertia.y()), jointtext::number(b.inertia.z()));
        }
        const int ti = model.bodyIndex(b.id);
        if (ti >= 0) tip << tr("moved by joint C %1").arg(model.jointId[static_cast<std::size_t>(ti)]);
        for (int c = 0; c < ColumnCount; ++c) item->setToolTip(c, tip.join(QLatin1Char('\n')));
    }

    // joints in file order
    QTreeWidgetItem* joints = addGroup(Group::Joints, tr("Joints (%1)").arg(spec.joints.size()));
    for (std::size_t k = 0; k < spec.joints.size(); ++k) addJoint(joints, static_cast<int>(k));

    // chains
    QTreeWidgetItem* chains = addGroup(Group::Chains, tr("Chains (%1)").arg(topo.chains.size()));
    for (std::size_t c = 0; c < topo.chains.size(); ++c) {
        QStringList ids;
        for (int k : topo.chains[c]) ids << tr("C %1").arg(spec.joints[static_cast<std::size_t>(k)].id);
        auto* item = new QTreeWidgetItem(chains, {tr("Chain %1:  %2").arg(c + 1).arg(ids.join(QStringLiteral(" → ")))});
        item->setData(0, ItemKindRole, static_cast<int>(ItemKind::Chain));
        item->setFirstColumnSpanned(true);
        for (int k : topo.chains[c]) addJoint(item, k);
    }

    // loop closures
    QTreeWidgetItem* loops = addGroup(Group::LoopClosures, tr("Loop closures (%1)").arg(topo.loopJoints.size()));
    for (int k : topo.loopJoints) addJoint(loops, k);
    if (topo.loopJoints.empty()) {
        auto* none = new QTreeWidgetItem(loops, {tr("none: the joints form an open tree")});
        none->setData(0, ItemKindRole, static_cast<int>(ItemKind::Info));
        none->setFirstColumnSpanned(true);
    }

    // coordinates: independent and dependent, with their initial values
    QTreeWidgetItem* coords = addGroup(Group::Coordinates, tr("Coordinates (degrees of freedom: %1)").arg(topo.dof));
    const auto addList = [&](const QString& title, const std::vector<int>& list) {
        auto* sub = new QTreeWidgetItem(coords, {title});
        sub->setData(0, ItemKindRole, static_cast<int>(ItemKind::Group));
        sub->setFirstColumnSpanned(true);
        for (int k : list) {
            QTreeWidgetItem* item = addJoint(sub, k);
            const solver::JointSpec& j = spec.joints[static_cast<std::size_t>(k)];
            if (static_cast<std::size_t>(k) < topo.q0.size()) {
                item->setText(DetailsColumn, tr("initially %1").arg(jointtext::coordinate(j.type, topo.q0[static_cast<std::size_t>(k)])));
            }
        }
        return sub;
    };
    addList(tr("Independent (%1)").arg(topo.independent.size()), topo.independent);
    addList(tr("Dependent (%1)").arg(topo.dependent.size()), topo.dependent);

    expandAll();
    for (int c = 0; c < ColumnCount - 1; ++c) resizeColumnToContents(c);
}

QTreeWidgetItem* ModelTree::groupItem(Group group) const { return m_groups[static_cast<int>(group)]; }

QTreeWidgetItem* ModelTree::findItem(ItemKind kind, int role, int value) const
{
    QTreeWidgetItem* group = groupItem(kind == ItemKind::Body ? Group::Bodies : Group::Joints);
    if (!group) return nullptr;
    for (int k = 0; k < group->childCount(); ++k) {
        QTreeWidgetItem* item = group->child(k);
        if (item->data(0, role).toInt() == value) return item;
    }
    return nullptr;
}

QTreeWidgetItem* ModelTree::bodyItem(int id) const { return findItem(ItemKind::Body, IdRole, id); }

QTreeWidgetItem* ModelTree::jointItem(int id) const { return findItem(ItemKind::Joint, IdRole, id); }

void ModelTree::selectBody(int treeIndex)
{
    QTreeWidgetItem* item = findItem(ItemKind::Body, TreeIndexRole, treeIndex);
    m_syncing = true;
    if (item) {
        setCurrentItem(item);
        scrollToItem(item);
    } else {
        clearSelection();
    }
    m_syncing = false;
}

void ModelTree::selectJoint(int treeIndex)
{
    QTreeWidgetItem* item = treeIndex >= 0 ? findItem(ItemKind::Joint, TreeIndexRole, treeIndex) : nullptr;
    m_syncing = true;
    if (item) {
        setCurrentItem(item);
        scrollToItem(item);
    } else {
        clearSelection();
    }
    m_syncing = false;
}

void ModelTree::onCurrentItemChanged(QTreeWidgetItem* current)
{
    if (m_syncing || !current) return;
    emitFor(current);
}

void ModelTree::emitFor(QTreeWidgetItem* item)
{
    if (!item) return;
    const auto kind = static_cast<ItemKind>(item->data(0, ItemKindRole).toInt());
    const int index = item->data(0, TreeIndexRole).toInt();
    const int line = item->data(0, LineRole).toInt();
    if (kind == ItemKind::Body) emit bodySelected(index);
    else if (kind == ItemKind::Joint) emit jointSelected(index);
    else return;
    if (line > 0) emit sourceSelected(line);
}

}  // namespace studio
