#pragma once
// SerialConsoleDialog: "Add serial console…" — the port of a replica console (the DAQ
// box, docs/daq-protocol.md) and its baud rate. The port combo is editable and lists
// the ports the system has now (QSerialPortInfo); the result is the profile's device
// setting "serial:<port>".

#include "trainer/station/profile.h"

#include <QDialog>
#include <QList>

class QComboBox;
class QDialogButtonBox;
class QFormLayout;
class QLabel;

namespace studio {

class SerialConsoleDialog : public QDialog {
    Q_OBJECT
public:
    explicit SerialConsoleDialog(QWidget* parent = nullptr);

    /// "serial:<port>" and the baud rate chosen.
    trainer::DeviceSetting setting() const;
    /// The port as typed or chosen ("" when none).
    QString port() const;
    int baud() const;

    QComboBox* portCombo() const { return m_port; }
    QComboBox* baudCombo() const { return m_baud; }
    QDialogButtonBox* buttons() const { return m_buttons; }

    /// 9600 … 921600.
    static QList<int> baudRates();

protected:
    /// QEvent::LanguageChange: retranslate().
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void portChanged();

    QLabel* m_intro = nullptr;
    QFormLayout* m_form = nullptr;
    QComboBox* m_port = nullptr;
    QComboBox* m_baud = nullptr;
    QLabel* m_about = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
};

}  // namespace studio
