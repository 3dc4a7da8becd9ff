#include "ide/studio/station/button_spin.h"

#include "trainer/station/control_names.h"

#include <QLineEdit>

#include <algorithm>

namespace studio {

void ButtonSpin::setGamepad(bool gamepad)
{
    if (gamepad == m_gamepad) return;
    m_gamepad = gamepad;
    // wide enough for the longest name ("Right stick press")
    int widest = 0;
    for (int b = 0; gamepad && !trainer::gamepadButtonName(b).isEmpty(); ++b)
        widest = std::max(widest, fontMetrics().horizontalAdvance(trainer::gamepadButtonName(b)));
    setMinimumWidth(widest > 0 ? widest + 40 : 0);
    lineEdit()->setText(value() == minimum() && !specialValueText().isEmpty() ? specialValueText()
                                                                              : textFromValue(value()));
}

QString ButtonSpin::textFromValue(int value) const
{
    const QString name = m_gamepad ? trainer::gamepadButtonName(value) : QString();
    return name.isEmpty() ? QSpinBox::textFromValue(value) : name;
}

int ButtonSpin::valueFromText(const QString& text) const
{
    for (int b = 0; m_gamepad && !trainer::gamepadButtonName(b).isEmpty(); ++b)
        if (trainer::gamepadButtonName(b).compare(text.trimmed(), Qt::CaseInsensitive) == 0) return b;
    return QSpinBox::valueFromText(text);
}

QValidator::State ButtonSpin::validate(QString& text, int& pos) const
{
    for (int b = 0; m_gamepad && !trainer::gamepadButtonName(b).isEmpty(); ++b) {
        const QString name = trainer::gamepadButtonName(b);
        if (name.compare(text.trimmed(), Qt::CaseInsensitive) == 0) return QValidator::Acceptable;
        if (name.startsWith(text.trimmed(), Qt::CaseInsensitive)) return QValidator::Intermediate;
    }
    return QSpinBox::validate(text, pos);
}

}  // namespace studio
