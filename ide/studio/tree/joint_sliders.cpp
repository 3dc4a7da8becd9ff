#include "ide/studio/tree/joint_sliders.h"

#include "ide/studio/tree/joint_text.h"
#include "solver/dynamics/constraints.h"
#include "solver/integrate/simulation.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace studio {

namespace {

constexpr int kSliderSteps = 10000;           // slider positions over a joint's range
constexpr double kMaxAngleStep = 2.0 * std::numbers::pi / 180.0;  // largest turn per closure [rad]
constexpr double kMaxLengthStep = 0.02;       // largest slide per closure, × Model::lengthScale
constexpr double kClosureTolerance = 1e-9;    // scaled loop-closure residual that counts as closed
constexpr int kRebuildAfter = 5000;           // setInitial() calls before the simulation is rebuilt

double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

}  // namespace

JointSliders::JointSliders(QWidget* parent) : QWidget(parent)
{
    auto* outer = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    m_reset = new QPushButton(this);
    m_reset->setEnabled(false);
    connect(m_reset, &QPushButton::clicked, this, &JointSliders::reset);
    top->addWidget(m_reset);
    top->addStretch(1);
    outer->addLayout(top);

    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_rowsWidget = new QWidget(scroll);
    m_grid = new QGridLayout(m_rowsWidget);
    m_grid->setColumnStretch(1, 1);
    scroll->setWidget(m_rowsWidget);
    outer->addWidget(scroll, 1);

    m_empty = new QLabel(this);
    m_empty->setWordWrap(true);
    outer->addWidget(m_empty);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    m_status->setStyleSheet(QStringLiteral("color: #b00020"));
    m_status->hide();
    outer->addWidget(m_status);
    retranslate();
}

JointSliders::~JointSliders() = default;

void JointSliders::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void JointSliders::retranslate()
{
    m_reset->setText(tr("Reset pose"));
    m_reset->setToolTip(tr("Back to the model's initial coordinates"));
    m_empty->setText(m_bundle ? tr("The model has no degrees of freedom to pose.") : tr("No model"));
    if (m_bundle) {
        const solver::ModelSpec& spec = m_bundle->spec();
        for (Row& row : m_rows) {
            const solver::JointSpec& js = spec.joints[static_cast<std::size_t>(row.specIndex)];
            row.label->setText(js.name.empty() ? tr("C %1").arg(js.id)
                                               : tr("C %1  %2").arg(js.id).arg(QString::fromStdString(js.name)));
            const QString tip = tr("%1, limits %2").arg(jointtext::typeName(js.type), jointtext::limits(js));
            row.label->setToolTip(tip);
            row.slider->setToolTip(tip);
            row.spin->setToolTip(tip);
            // the spin box writes its number in the locale it has (1,5 in Spanish)
            row.spin->setLocale(QLocale());
            row.spin->setSuffix(jointtext::isLength(js.type) ? tr(" m") : tr(" °"));
        }
    }
    if (m_statusText) m_status->setText(m_statusText());
}

void JointSliders::setStatus(std::function<QString()> text)
{
    m_statusText = std::move(text);
    m_status->setText(m_statusText ? m_statusText() : QString());
}

void JointSliders::setBundle(std::shared_ptr<const ModelBundle> bundle)
{
    m_bundle = std::move(bundle);
    m_sim.reset();
    if (m_bundle) rebuildSimulation(nullptr);
    buildRows();
    setStatus({});
    m_status->hide();
}

void JointSliders::rebuildSimulation(const Eigen::VectorXd* goodTheta)
{
    // drives and limits off: every coordinate that is not set follows the loops
    solver::SimulationOptions options;
    options.drives = false;
    options.limits = false;
    m_sim = std::make_unique<solver::Simulation>(m_bundle->model, options);
    m_setCalls = 0;
    if (!goodTheta) return;
    const solver::Model& m = m_sim->model();
    if (m.cuts.empty()) {
        for (int j = 0; j < m.nb; ++j) m_sim->setInitial(j, (*goodTheta)[j], 0);
        return;
    }
    // with loops, walk the independent coordinates from the initial ones to the good
    // ones in small steps, so the loops stay in the assembly they were in
    std::vector<int> independent;
    for (int j = 0; j < m.nb; ++j) {
        if (!m.dependent[static_cast<std::size_t>(j)]) independent.push_back(j);
    }
    const Eigen::VectorXd start = m_sim->state().q;
    int steps = 0;
    for (int j : independent) {
        const double maxStep = m.jointType[static_cast<std::size_t>(j)] == solver::JointType::Prismatic
                                   ? kMaxLengthStep * m.lengthScale
                                   : kMaxAngleStep;
        steps = std::max(steps, static_cast<int>(std::ceil(std::abs((*goodTheta)[j] - start[j]) / maxStep)));
    }
    const auto walk = [&](int upTo) {
        for (int i = 1; i <= upTo; ++i) {
            bool ok = true;
            for (int j : independent) {
                const double theta = start[j] + ((*goodTheta)[j] - start[j]) * i / steps;
                m_sim->setInitial(j, theta, 0);
                ++m_setCalls;
                ok = ok && closed(j, theta);
            }
            if (!ok) return i - 1;
        }
        return upTo;
    };
    const int reached = walk(steps);
    if (reached < steps) {
        // the last step broke the loops: walk again to the step before it
        m_sim = std::make_unique<solver::Simulation>(m_bundle->model, options);
        m_setCalls = 0;
        walk(reached);
    }
}

bool JointSliders::closed(int joint, double theta) const
{
    const solver::State& s = m_sim->state();
    if (!(std::abs(s.q[joint] - theta) <= kClosureTolerance * (1 + std::abs(theta)))) return false;
    const solver::Model& m = m_sim->model();
    if (m.cuts.empty()) return true;
    std::vector<solver::Constraint> constraints;
    solver::collectConstraints(m, s, constraints);
    Eigen::VectorXd phi;
    solver::constraintResidual(m, m_sim->data(), constraints, phi);
    return phi.size() == 0 || phi.lpNorm<Eigen::Infinity>() <= kClosureTolerance;
}

bool JointSliders::stepTo(int joint, double theta)
{
    const solver::Model& m = m_sim->model();
    const double from = m_sim->state().q[joint];
    if (m.cuts.empty()) {
        m_sim->setInitial(joint, theta, 0);
        return true;
    }
    const double maxStep =
        m.jointType[static_cast<std::size_t>(joint)] == solver::JointType::Prismatic ? kMaxLengthStep * m.lengthScale : kMaxAngleStep;
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(theta - from) / maxStep)));
    for (int i = 1; i <= steps; ++i) {
        const Eigen::VectorXd good = m_sim->state().q;
        const double t = i == steps ? theta : from + (theta - from) * i / steps;
        m_sim->setInitial(joint, t, 0);
        ++m_setCalls;
        if (!closed(joint, t)) {
            rebuildSimulation(&good);  // back to the last pose that closed
            return false;
        }
    }
    if (m_setCalls > kRebuildAfter) {
        // setInitial() remembers every joint set until the next step: start afresh
        const Eigen::VectorXd now = m_sim->state().q;
        rebuildSimulation(&now);
    }
    return true;
}

void JointSliders::buildRows()
{
    // remove the old rows
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_rows.clear();
    m_reset->setEnabled(false);
    if (!m_bundle) {
        retranslate();
        m_empty->show();
        return;
    }
    const solver::ModelSpec& spec = m_bundle->spec();
    const solver::Topology& topo = m_bundle->topology();
    const solver::Model& model = m_sim->model();
    const solver::State& s = m_sim->state();
    for (int specIndex : topo.independent) {
        const solver::JointSpec& js = spec.joints[static_cast<std::size_t>(specIndex)];
        if (js.type == solver::JointType::Free) continue;  // six coordinates: moved by forces and contacts
        Row row;
        row.specIndex = specIndex;
        row.jointId = js.id;
        row.joint = model.jointIndex(js.id);
        if (row.joint < 0) continue;
        row.type = js.type;
        const double q0 = model.coordinate(row.joint, s.q[row.joint]);
        // the range: the limits, or what the joint can sensibly reach
        double lo = 0, hi = 0;
        switch (js.type) {
        case solver::JointType::Revolute:
            lo = js.ll.value_or(-std::numbers::pi);
            hi = js.ul.value_or(std::numbers::pi);
            if (!js.ul && hi <= lo) hi = lo + 2 * std::numbers::pi;
            if (!js.ll && lo >= hi) lo = hi - 2 * std::numbers::pi;
            break;
        case solver::JointType::Actuator: {
            const solver::ActuatorLengthLaw& law = model.lengthLaw[static_cast<std::size_t>(row.joint)];
            lo = js.ll.value_or(law.minLength());
            hi = js.ul.value_or(law.maxLength());
            break;
        }
        case solver::JointType::Prismatic:
        case solver::JointType::Free: {  // (not reached: left out above)
            const double reach = model.lengthScale;
            lo = js.ll.value_or(std::min(q0, js.ul.value_or(q0)) - reach);
            hi = js.ul.value_or(std::max(q0, js.ll.value_or(q0)) + reach);
            break;
        }
        }
        lo = std::min(lo, q0);
        hi = std::max(hi, q0);
        if (!(hi > lo)) hi = lo + (jointtext::isLength(js.type) ? 1e-3 : 1e-3 * std::numbers::pi / 180);
        row.lo = lo;
        row.hi = hi;

        const int r = static_cast<int>(m_rows.size());
        // (the texts: retranslate())
        row.label = new QLabel(m_rowsWidget);
        row.slider = new QSlider(Qt::Horizontal, m_rowsWidget);
        row.slider->setRange(0, kSliderSteps);
        row.spin = new QDoubleSpinBox(m_rowsWidget);
        row.spin->setKeyboardTracking(false);
        row.spin->setDecimals(jointtext::isLength(js.type) ? 4 : 2);
        row.spin->setRange(displayValue(row, lo), displayValue(row, hi));
        row.spin->setSingleStep(jointtext::isLength(js.type) ? std::max(1e-4, (hi - lo) / 100) : 1.0);
        m_grid->addWidget(row.label, r, 0);
        m_grid->addWidget(row.slider, r, 1);
        m_grid->addWidget(row.spin, r, 2);
        connect(row.slider, &QSlider::valueChanged, this, [this, r](int v) {
            const Row& row = m_rows[static_cast<std::size_t>(r)];
            moveRow(r, row.lo + (row.hi - row.lo) * v / kSliderSteps);
        });
        connect(row.spin, &QDoubleSpinBox::valueChanged, this, [this, r](double v) {
            const Row& row = m_rows[static_cast<std::size_t>(r)];
            moveRow(r, jointtext::isLength(row.type) ? v : v * std::numbers::pi / 180);
        });
        m_rows.push_back(row);
    }
    m_grid->setRowStretch(static_cast<int>(m_rows.size()), 1);
    retranslate();
    m_empty->setVisible(m_rows.empty());
    m_reset->setEnabled(!m_rows.empty());
    showValues();
}

double JointSliders::displayValue(const Row& row, double q) const
{
    return jointtext::isLength(row.type) ? q : degrees(q);
}

bool JointSliders::moveRow(int k, double q)
{
    if (!m_sim || k < 0 || k >= sliderCount()) return false;
    const Row& row = m_rows[static_cast<std::size_t>(k)];
    const double current = m_sim->state().q[row.joint];
    double theta = q;
    bool ok = true;
    if (row.type == solver::JointType::Actuator) {
        // the length's angle on the branch the joint is on
        const auto angle = m_sim->model().lengthLaw[static_cast<std::size_t>(row.joint)].angleNear(q, current, 1e-9);
        if (!angle) {
            ok = false;
            setStatus([this, id = row.jointId, type = row.type, q] {
                return tr("C %1 cannot reach the length %2: kept the last pose.").arg(id).arg(jointtext::coordinate(type, q));
            });
        } else {
            theta = *angle;
        }
    }
    if (ok && theta != current) {
        ok = stepTo(row.joint, theta);
        if (!ok) {
            const double reached = m_sim->model().coordinate(row.joint, m_sim->state().q[row.joint]);
            setStatus([this, id = row.jointId, type = row.type, q, reached] {
                return tr("The loops cannot close with C %1 at %2: the pose stops at %3, the last one that closes.")
                    .arg(id)
                    .arg(jointtext::coordinate(type, q), jointtext::coordinate(type, reached));
            });
        }
    }
    m_status->setVisible(!ok);
    showValues();
    publish(true);
    return ok;
}

bool JointSliders::setCoordinate(int k, double q) { return moveRow(k, q); }

void JointSliders::reset()
{
    if (!m_bundle) return;
    rebuildSimulation(nullptr);
    setStatus({});
    m_status->hide();
    showValues();
    publish(true);
}

void JointSliders::showState(const Eigen::VectorXd& theta)
{
    if (!m_sim) return;
    const int nb = m_sim->model().nb;
    if (theta.size() < nb || theta.head(nb) == m_sim->state().q.head(nb)) return;
    placeAt(theta);
    setStatus({});
    m_status->hide();
    showValues();
}

void JointSliders::placeAt(const Eigen::VectorXd& theta)
{
    const int nb = m_sim->model().nb;
    if (m_setCalls + nb > kRebuildAfter) rebuildSimulation(nullptr);
    for (int j = 0; j < nb; ++j) m_sim->setInitial(j, theta[j], 0);
    m_setCalls += nb;
    // with loops, a step of no time ends the set-up: the joints set are no longer held,
    // so the next move turns only its own joint and the loops follow (not with free
    // joints: the step would fold their turns into an orientation the solver thread's
    // simulation does not share)
    const solver::Model& m = m_sim->model();
    if (m.cuts.empty() || !m.freeJoints.empty()) return;
    std::vector<solver::SimulationEvent> events;
    std::string error;
    m_sim->advanceTo(m_sim->state().t, events, error);
}

void JointSliders::showValues()
{
    if (!m_sim) return;
    const solver::Model& m = m_sim->model();
    for (Row& row : m_rows) {
        const double q = m.coordinate(row.joint, m_sim->state().q[row.joint]);
        const QSignalBlocker b1(row.slider);
        const QSignalBlocker b2(row.spin);
        row.slider->setValue(static_cast<int>(std::lround(std::clamp((q - row.lo) / (row.hi - row.lo), 0.0, 1.0) * kSliderSteps)));
        row.spin->setValue(displayValue(row, q));
    }
}

void JointSliders::publish(bool edited)
{
    emit posesChanged(m_sim->data().X_wb);
    emit coordinatesChanged(coordinates());
    if (edited) emit poseEdited(m_sim->state().q.head(m_sim->model().nb));
}

int JointSliders::sliderJoint(int k) const { return m_rows.at(static_cast<std::size_t>(k)).joint; }

QSlider* JointSliders::slider(int k) const { return m_rows.at(static_cast<std::size_t>(k)).slider; }

QDoubleSpinBox* JointSliders::spinBox(int k) const { return m_rows.at(static_cast<std::size_t>(k)).spin; }

double JointSliders::lower(int k) const { return m_rows.at(static_cast<std::size_t>(k)).lo; }

double JointSliders::upper(int k) const { return m_rows.at(static_cast<std::size_t>(k)).hi; }

const std::vector<Eigen::Isometry3d>& JointSliders::poses() const
{
    static const std::vector<Eigen::Isometry3d> none;
    return m_sim ? m_sim->data().X_wb : none;
}

Eigen::VectorXd JointSliders::coordinates() const
{
    if (!m_sim) return {};
    const solver::Model& m = m_sim->model();
    Eigen::VectorXd q(m.nb);
    for (int j = 0; j < m.nb; ++j) q[j] = m.coordinate(j, m_sim->state().q[j]);
    return q;
}

Eigen::VectorXd JointSliders::theta() const { return m_sim ? m_sim->state().q : Eigen::VectorXd(); }

QString JointSliders::status() const { return m_status->isHidden() ? QString() : m_status->text(); }

}  // namespace studio
