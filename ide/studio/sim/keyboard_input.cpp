#include "ide/studio/sim/keyboard_input.h"

#include "ide/studio/sim/simulation_runner.h"

#include <QKeyEvent>
#include <QKeySequence>
#include <QWidget>

#include <algorithm>
#include <array>
#include <utility>

namespace studio {

namespace {

// first key u = +1, second u = −1, in the order the drives get them
constexpr std::array<std::pair<Qt::Key, Qt::Key>, 9> kPairs = {{
    {Qt::Key_Q, Qt::Key_A},
    {Qt::Key_W, Qt::Key_S},
    {Qt::Key_E, Qt::Key_D},
    {Qt::Key_R, Qt::Key_F},
    {Qt::Key_T, Qt::Key_G},
    {Qt::Key_Y, Qt::Key_H},
    {Qt::Key_U, Qt::Key_J},
    {Qt::Key_I, Qt::Key_K},
    {Qt::Key_O, Qt::Key_L},
}};

}  // namespace

QString KeyBinding::keysText() const
{
    return QStringLiteral("%1 / %2").arg(QKeySequence(plusKey).toString(QKeySequence::NativeText),
                                         QKeySequence(minusKey).toString(QKeySequence::NativeText));
}

KeyboardInput::KeyboardInput(SimulationRunner* runner, QObject* parent) : QObject(parent), m_runner(runner)
{
    if (runner) {
        connect(runner, &SimulationRunner::bundleChanged, this, [this] {
            if (m_runner) setBundle(m_runner->bundle());
        });
        setBundle(runner->bundle());
    }
}

KeyboardInput::~KeyboardInput() = default;

QStringList KeyboardInput::pairNames()
{
    QStringList names;
    for (const auto& [plus, minus] : kPairs)
        names << QStringLiteral("%1 / %2").arg(QKeySequence(plus).toString(QKeySequence::NativeText),
                                               QKeySequence(minus).toString(QKeySequence::NativeText));
    return names;
}

bool KeyboardInput::isValveKey(int key)
{
    return std::any_of(kPairs.begin(), kPairs.end(), [key](const auto& pair) {
        return pair.first == key || pair.second == key;
    });
}

void KeyboardInput::setDevice(std::shared_ptr<trainer::KeyboardDevice> device)
{
    releaseAll();
    m_device = std::move(device);
}

void KeyboardInput::setBundle(std::shared_ptr<const ModelBundle> bundle)
{
    releaseAll();
    m_bindings.clear();
    if (bundle && bundle->model) {
        const solver::Model& m = *bundle->model;
        std::vector<int> drives;
        for (int i = 0; i < m.nb; ++i) {
            if (m.drive[std::size_t(i)].type != solver::DriveType::None) drives.push_back(i);
        }
        std::sort(drives.begin(), drives.end(), [&](int a, int b) {
            return m.jointId[std::size_t(a)] < m.jointId[std::size_t(b)];
        });
        for (std::size_t k = 0; k < drives.size() && k < kPairs.size(); ++k) {
            KeyBinding b;
            b.plusKey = kPairs[k].first;
            b.minusKey = kPairs[k].second;
            b.treeJoint = drives[k];
            b.jointId = m.jointId[std::size_t(drives[k])];
            b.jointName = QString::fromStdString(m.jointName[std::size_t(drives[k])]);
            m_bindings.append(b);
        }
    }
    m_held.assign(std::size_t(m_bindings.size()), Held{});
    emit bindingsChanged();
}

QStringList KeyboardInput::describe() const
{
    QStringList lines;
    for (const KeyBinding& b : m_bindings) {
        lines << (b.jointName.isEmpty() ? tr("%1 — C %2").arg(b.keysText()).arg(b.jointId)
                                        : tr("%1 — C %2 %3").arg(b.keysText()).arg(b.jointId).arg(b.jointName));
    }
    return lines;
}

void KeyboardInput::attachTo(QWidget* widget)
{
    if (widget) widget->installEventFilter(this);
}

void KeyboardInput::detachFrom(QWidget* widget)
{
    if (!widget) return;
    widget->removeEventFilter(this);
    releaseAll();
}

void KeyboardInput::setEnabled(bool enabled)
{
    if (!enabled) releaseAll();
    m_enabled = enabled;
}

void KeyboardInput::releaseAll()
{
    for (std::size_t k = 0; k < m_held.size(); ++k) {
        if (!m_held[k].plus && !m_held[k].minus) continue;
        m_held[k] = Held{};
        update(int(k));
    }
}

double KeyboardInput::command(int treeJoint) const
{
    for (qsizetype k = 0; k < m_bindings.size(); ++k) {
        if (m_bindings[k].treeJoint != treeJoint) continue;
        const Held& h = m_held[std::size_t(k)];
        return (h.plus ? 1.0 : 0.0) - (h.minus ? 1.0 : 0.0);
    }
    return 0;
}

bool KeyboardInput::find(int key, int& binding, int& direction) const
{
    for (qsizetype k = 0; k < m_bindings.size(); ++k) {
        if (m_bindings[k].plusKey == key || m_bindings[k].minusKey == key) {
            binding = int(k);
            direction = m_bindings[k].plusKey == key ? 1 : -1;
            return true;
        }
    }
    return false;
}

void KeyboardInput::update(int binding)
{
    const KeyBinding& b = m_bindings[binding];
    const double u = command(b.treeJoint);
    if (m_device) {
        // pair k is the keyboard device's channel k; the station maps it
        const Held& h = m_held[std::size_t(binding)];
        m_device->setKeys(binding, h.plus, h.minus);
    } else if (m_runner) {
        m_runner->setCommand(b.treeJoint, u);
    }
    emit commandChanged(b.treeJoint, u);
}

bool KeyboardInput::eventFilter(QObject* watched, QEvent* event)
{
    switch (event->type()) {
    case QEvent::FocusOut:
    case QEvent::WindowDeactivate:
    case QEvent::Hide:
        releaseAll();
        break;
    case QEvent::ShortcutOverride:
    case QEvent::KeyPress:
    case QEvent::KeyRelease: {
        if (!m_enabled) break;
        auto* key = static_cast<QKeyEvent*>(event);
        int binding = 0, direction = 0;
        if (!find(key->key(), binding, direction)) break;
        const bool press = event->type() != QEvent::KeyRelease;
        constexpr Qt::KeyboardModifiers shortcuts = Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier;
        if (press && (key->modifiers() & shortcuts)) break;  // a shortcut, not a drive
        if (event->type() == QEvent::ShortcutOverride) {
            // ours: no single-letter shortcut may take it
            event->accept();
            return true;
        }
        if (key->isAutoRepeat()) return true;
        Held& h = m_held[std::size_t(binding)];
        bool& down = direction > 0 ? h.plus : h.minus;
        if (down != press) {
            down = press;
            update(binding);
        }
        return true;
    }
    default:
        break;
    }
    return QObject::eventFilter(watched, event);
}

}  // namespace studio
