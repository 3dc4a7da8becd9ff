#include "ide/studio/station/serial_console_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QVBoxLayout>

namespace studio {

QList<int> SerialConsoleDialog::baudRates()
{
    return {9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600};
}

SerialConsoleDialog::SerialConsoleDialog(QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("Add serial console"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("A replica console (levers on a DAQ box) on a serial port. The station opens it "
                                "while this profile is in use, and tries again when it is unplugged."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto* form = new QFormLayout;
    m_port = new QComboBox(this);
    m_port->setEditable(true);
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setMinimumWidth(280);
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts()) {
        QStringList about;
        if (!info.description().isEmpty()) about << info.description();
        if (!info.manufacturer().isEmpty()) about << info.manufacturer();
        if (!info.serialNumber().isEmpty()) about << tr("serial number %1").arg(info.serialNumber());
        m_port->addItem(info.systemLocation(), about.join(QStringLiteral(", ")));
        m_port->setItemData(m_port->count() - 1, about.join(QStringLiteral(", ")), Qt::ToolTipRole);
    }
    m_port->lineEdit()->setPlaceholderText(tr("e.g. /dev/ttyACM0"));
    m_port->setToolTip(tr("The port's name exactly as the profile will keep it (a /dev/serial/by-id/… link stays "
                          "the same when the box is plugged elsewhere)"));
    form->addRow(tr("Port:"), m_port);
    m_about = new QLabel(this);
    m_about->setWordWrap(true);
    form->addRow(QString(), m_about);
    m_baud = new QComboBox(this);
    for (int rate : baudRates()) m_baud->addItem(QString::number(rate), rate);
    m_baud->setCurrentIndex(baudRates().indexOf(115200));
    form->addRow(tr("Baud rate:"), m_baud);
    layout->addLayout(form);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Add"));
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(m_buttons);

    connect(m_port, &QComboBox::currentTextChanged, this, &SerialConsoleDialog::portChanged);
    portChanged();
}

void SerialConsoleDialog::portChanged()
{
    const int i = m_port->findText(m_port->currentText());
    if (m_port->count() == 0) m_about->setText(tr("No serial port found now; type the port's name."));
    else m_about->setText(i >= 0 ? m_port->itemData(i).toString() : QString());
    m_about->setVisible(!m_about->text().isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(!port().isEmpty());
}

QString SerialConsoleDialog::port() const
{
    return m_port->currentText().trimmed();
}

int SerialConsoleDialog::baud() const
{
    return m_baud->currentData().toInt();
}

trainer::DeviceSetting SerialConsoleDialog::setting() const
{
    return {QStringLiteral("serial:") + port(), baud()};
}

}  // namespace studio
