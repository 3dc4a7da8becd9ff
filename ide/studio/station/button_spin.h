#pragma once
// ButtonSpin: a device's button number (−1 "none") in the Station workspace's banks,
// shown by its name when the device is a gamepad ("Left shoulder", SDL's
// game-controller layout, trainer/station/control_names.h) and typed as a name or a
// number; any other device's button by its number.

#include <QSpinBox>

namespace studio {

class ButtonSpin : public QSpinBox {
    Q_OBJECT
public:
    using QSpinBox::QSpinBox;

    /// Names the buttons as a gamepad's (true) or numbers them (false).
    void setGamepad(bool gamepad);
    bool isGamepad() const { return m_gamepad; }

protected:
    QString textFromValue(int value) const override;
    int valueFromText(const QString& text) const override;
    QValidator::State validate(QString& text, int& pos) const override;

private:
    bool m_gamepad = false;
};

}  // namespace studio
