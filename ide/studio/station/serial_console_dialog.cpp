#include "ide/studio/station/serial_console_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QEvent>
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
    auto* layout = new QVBoxLayout(this);
    m_intro = new QLabel(this);
    m_intro->setWordWrap(true);
    layout->addWidget(m_intro);

    m_form = new QFormLayout;
    m_port = new QComboBox(this);
    m_port->setEditable(true);
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setMinimumWidth(280);
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts()) m_port->addItem(info.systemLocation());
    m_form->addRow(QStringLiteral("-"), m_port);
    m_about = new QLabel(this);
    m_about->setWordWrap(true);
    m_form->addRow(QString(), m_about);
    m_baud = new QComboBox(this);
    for (int rate : baudRates()) m_baud->addItem(QString::number(rate), rate);
    m_baud->setCurrentIndex(baudRates().indexOf(115200));
    m_form->addRow(QStringLiteral("-"), m_baud);
    layout->addLayout(m_form);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(m_buttons);

    connect(m_port, &QComboBox::currentTextChanged, this, &SerialConsoleDialog::portChanged);
    retranslate();
}

void SerialConsoleDialog::retranslate()
{
    setWindowTitle(tr("Add serial console"));
    m_intro->setText(tr("A replica console (levers on a DAQ box) on a serial port. The station opens it while this "
                        "profile is in use, and tries again when it is unplugged."));
    // what each port is (its description, maker, serial number), as its data and tooltip
    const QList<QSerialPortInfo> ports = QSerialPortInfo::availablePorts();
    for (int i = 0; i < m_port->count(); ++i) {
        QStringList about;
        for (const QSerialPortInfo& info : ports) {
            if (info.systemLocation() != m_port->itemText(i)) continue;
            if (!info.description().isEmpty()) about << info.description();
            if (!info.manufacturer().isEmpty()) about << info.manufacturer();
            if (!info.serialNumber().isEmpty()) about << tr("serial number %1").arg(info.serialNumber());
        }
        m_port->setItemData(i, about.join(QStringLiteral(", ")));
        m_port->setItemData(i, about.join(QStringLiteral(", ")), Qt::ToolTipRole);
    }
    m_port->lineEdit()->setPlaceholderText(tr("e.g. /dev/ttyACM0"));
    m_port->setToolTip(tr("The port's name exactly as the profile will keep it (a /dev/serial/by-id/… link stays "
                          "the same when the box is plugged elsewhere)"));
    qobject_cast<QLabel*>(m_form->labelForField(m_port))->setText(tr("Port:"));
    qobject_cast<QLabel*>(m_form->labelForField(m_baud))->setText(tr("Baud rate:"));
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Add"));
    m_buttons->button(QDialogButtonBox::Cancel)->setText(tr("Cancel"));
    portChanged();
}

void SerialConsoleDialog::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslate();
    QDialog::changeEvent(event);
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
