#pragma once
// The trainer's PIN, asked before the kiosk gives way (leaving Trainer Mode, the
// trainee records). One dialog for both: a wrong PIN is said so and can be typed
// again; five wrong ones in a row lock the dialog for half a minute.

#include <QDialog>
#include <QString>

class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QTimer;

namespace studio {

class PinDialog : public QDialog {
    Q_OBJECT
public:
    /// The trainer's PIN as set (QSettings "trainer/pin"); empty: none.
    static QString trainerPin();
    /// How many wrong PINs in a row lock the dialog, and for how long.
    static constexpr int kMaxWrong = 5;
    static constexpr int kLockSeconds = 30;

    /// `title` and `prompt` are already translated. Deletes itself when closed.
    PinDialog(const QString& title, const QString& prompt, QWidget* parent);

    QLineEdit* field() const { return m_field; }
    QLabel* message() const { return m_message; }
    /// OK: unlocked() and closes at the right PIN; otherwise says so and stays.
    void submit();
    bool isLocked() const;

signals:
    void unlocked();

private:
    void tick();
    void showLock();

    QLineEdit* m_field = nullptr;
    QLabel* m_message = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
    QTimer* m_lock = nullptr;
    int m_wrong = 0;
    int m_lockLeft = 0;
};

}  // namespace studio
