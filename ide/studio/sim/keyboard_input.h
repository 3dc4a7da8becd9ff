#pragma once
// KeyboardInput: drives the machine from the keyboard, two keys per drive. The
// drives (tree joints with a D statement) in the order of their joint ids get the
// pairs Q/A, W/S, E/D, R/F, T/G, Y/H, U/J, I/K, O/L: holding the first key commands
// u = +1, the second u = −1, both or neither 0. A model with more than nine drives
// leaves the rest to other devices.
//
// Install it as an event filter on the widget that has the keyboard focus (the 3D
// viewport) with attachTo(). Auto-repeated presses are ignored; presses with Ctrl,
// Alt or Meta are left to shortcuts (their releases still count). When that widget
// loses the focus or the window is deactivated every key is released, so a drive
// never keeps moving because its key-up went to another window. Keys are Qt key codes
// (the letters printed on the keys, so an AZERTY keyboard's pairs are where the
// letters are).
//
// It writes commands into a SimulationRunner (setCommand) and follows its model
// (bundleChanged) — or, once setDevice() gave it the station's keyboard device, it
// only reports the keys there (pair k = the device's channel k) and the station maps
// them like any other device.

#include "ide/studio/model/model_bundle.h"
#include "trainer/input/keyboard_device.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>

#include <memory>
#include <vector>

class QWidget;

namespace studio {

class SimulationRunner;

/// One key pair of KeyboardInput's mapping.
struct KeyBinding {
    int plusKey = 0;    ///< Qt::Key giving u = +1
    int minusKey = 0;   ///< Qt::Key giving u = −1
    int treeJoint = 0;  ///< the drive's joint (tree index)
    int jointId = 0;    ///< its id in the model (C id)
    QString jointName;  ///< its NAME ("" when unnamed)

    /// The pair as shown to the user, e.g. "Q / A".
    QString keysText() const;
};

class KeyboardInput : public QObject {
    Q_OBJECT
public:
    /// Follows `runner`'s model (may be nullptr: then nothing is written).
    explicit KeyboardInput(SimulationRunner* runner, QObject* parent = nullptr);
    ~KeyboardInput() override;

    /// The nine pairs as shown, "Q / A" … "O / L" (the keyboard device's channels).
    static QStringList pairNames();
    /// `key` (a Qt::Key, no modifiers) opens a valve: a key of one of the pairs. No
    /// shortcut of the application may be one (they would never reach the valves, or
    /// the valves would take them).
    static bool isValveKey(int key);
    /// From now on the keys go to `device` (channel k = pair k), not to the runner;
    /// nullptr: back to the runner. Every key is released.
    void setDevice(std::shared_ptr<trainer::KeyboardDevice> device);

    /// Rebuilds the mapping for `bundle` (called on the runner's bundleChanged());
    /// every key is released.
    void setBundle(std::shared_ptr<const ModelBundle> bundle);

    /// The mapping, in joint id order.
    const QList<KeyBinding>& bindings() const { return m_bindings; }
    /// The mapping as lines "Q / A — C 2 LEVANTE PLUMA", for a help panel.
    QStringList describe() const;

    /// Listens to the keys sent to `widget` (installs this as its event filter).
    void attachTo(QWidget* widget);
    void detachFrom(QWidget* widget);

    /// Disabled: every key released and ignored.
    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }

    /// Releases every key (commands of the mapped drives back to 0).
    void releaseAll();
    /// The command this input gives tree joint `treeJoint` now (0 when unmapped).
    double command(int treeJoint) const;

    bool eventFilter(QObject* watched, QEvent* event) override;

signals:
    void bindingsChanged();
    /// A mapped drive's command changed (key pressed or released).
    void commandChanged(int treeJoint, double u);

private:
    struct Held {
        bool plus = false, minus = false;
    };
    /// The binding index and direction (+1/−1) of `key`; false when unmapped.
    bool find(int key, int& binding, int& direction) const;
    void update(int binding);

    QPointer<SimulationRunner> m_runner;
    std::shared_ptr<trainer::KeyboardDevice> m_device;
    QList<KeyBinding> m_bindings;
    std::vector<Held> m_held;
    bool m_enabled = true;
};

}  // namespace studio
