#include "ide/studio/train/pin_dialog.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QTimer>
#include <QVBoxLayout>

namespace studio {

QString PinDialog::trainerPin()
{
    return QSettings().value("trainer/pin").toString();
}

PinDialog::PinDialog(const QString& title, const QString& prompt, QWidget* parent) : QDialog(parent)
{
    setAttribute(Qt::WA_DeleteOnClose);
    setWindowTitle(title);
    setMinimumWidth(380);  // the message on one or two whole lines, in Spanish too
    auto* layout = new QVBoxLayout(this);
    auto* label = new QLabel(prompt);
    layout->addWidget(label);
    m_field = new QLineEdit;
    m_field->setObjectName("PinField");
    m_field->setEchoMode(QLineEdit::Password);
    label->setBuddy(m_field);
    layout->addWidget(m_field);
    m_message = new QLabel;
    m_message->setObjectName("PinMessage");
    m_message->setWordWrap(true);
    m_message->setStyleSheet("color: #b00020;");
    m_message->hide();
    layout->addWidget(m_message);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("OK"));
    m_buttons->button(QDialogButtonBox::Cancel)->setText(tr("Cancel"));
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &PinDialog::submit);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    m_lock = new QTimer(this);
    m_lock->setInterval(1000);
    connect(m_lock, &QTimer::timeout, this, &PinDialog::tick);
}

bool PinDialog::isLocked() const
{
    return m_lockLeft > 0;
}

void PinDialog::submit()
{
    if (isLocked()) return;
    if (!trainerPin().isEmpty() && m_field->text() == trainerPin()) {
        emit unlocked();
        accept();
        return;
    }
    m_field->clear();
    m_field->setFocus();
    if (++m_wrong >= kMaxWrong) {
        m_wrong = 0;
        m_lockLeft = kLockSeconds;
        m_field->setEnabled(false);
        m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
        m_lock->start();
        showLock();
        return;
    }
    m_message->setText(tr("That is not the trainer's PIN. Try again."));
    m_message->show();
    adjustSize();  // room for the message, not a clipped line
}

void PinDialog::tick()
{
    if (--m_lockLeft <= 0) {
        m_lock->stop();
        m_lockLeft = 0;
        m_field->setEnabled(true);
        m_buttons->button(QDialogButtonBox::Ok)->setEnabled(true);
        m_field->setFocus();
        m_message->setText(tr("Type the trainer's PIN."));
        return;
    }
    showLock();
}

void PinDialog::showLock()
{
    m_message->setText(tr("Too many wrong PINs: wait %n s.", nullptr, m_lockLeft));
    m_message->show();
    adjustSize();
}

}  // namespace studio
