#pragma once
// GettingStarted: the first-run overlay (issue 25, item 13). A small window over the
// main window that says, in the UI's language, how to run and pause the simulation
// (the Simulation menu's actions and their shortcuts), how the keys drive the machine
// (hold a key pair with the 3D view focused; the Train workspace names each stage's
// keys and levers) and how the mouse moves the view (orbit, pan, zoom, fit). Shown
// once: "Got it" remembers it in QSettings (kShownKey); Help ▸ Getting Started opens it
// again. Frameless and over the window (a separate window: the 3D views' native windows
// would hide a child widget).

#include "ide/i18n/texts.h"

#include <QFrame>
#include <QList>

class QAction;
class QLabel;
class QPushButton;

namespace studio {

class GettingStarted : public QFrame {
    Q_OBJECT
public:
    /// QSettings key: the overlay was dismissed once.
    static constexpr const char* kShownKey = "help/gettingStartedShown";

    /// `run`, `pause`: the Simulation menu's actions (their shortcuts are named).
    GettingStarted(QWidget* window, QAction* run, QAction* pause);

    /// Shown over the window's centre (again, from the Help menu).
    void open();
    /// Whether it has been dismissed once (QSettings).
    static bool wasShown();

    QLabel* text() const { return m_text; }
    QPushButton* closeButton() const { return m_close; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void fill();

    QWidget* m_window;
    QAction* m_run;
    QAction* m_pause;
    QLabel* m_title = nullptr;
    QLabel* m_text = nullptr;
    QPushButton* m_close = nullptr;
};

}  // namespace studio
