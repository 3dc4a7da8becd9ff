#include "ide/studio/app/getting_started.h"

#include "ide/studio/sim/keyboard_input.h"

#include <QAction>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

namespace studio {

GettingStarted::GettingStarted(QWidget* window, QAction* run, QAction* pause)
    : QFrame(window, Qt::Tool | Qt::FramelessWindowHint), m_window(window), m_run(run), m_pause(pause)
{
    setObjectName("GettingStarted");
    setAttribute(Qt::WA_ShowWithoutActivating, false);
    setStyleSheet("QFrame#GettingStarted { background: rgb(28, 34, 40); border: 2px solid #1f6fc5; border-radius: 10px; }"
                  "QLabel { color: white; font-size: 13pt; } QLabel#GettingStartedTitle { font-size: 18pt; "
                  "font-weight: bold; }");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(24, 18, 24, 18);
    m_title = new QLabel;
    m_title->setObjectName("GettingStartedTitle");
    m_text = new QLabel;
    m_text->setObjectName("GettingStartedText");
    m_text->setTextFormat(Qt::RichText);
    m_text->setWordWrap(true);
    m_close = new QPushButton;
    m_close->setObjectName("GettingStartedClose");
    m_close->setDefault(true);
    layout->addWidget(m_title);
    layout->addWidget(m_text, 1);
    auto* row = new QHBoxLayout;
    row->addStretch();
    row->addWidget(m_close);
    layout->addLayout(row);
    connect(m_close, &QPushButton::clicked, this, [this] {
        QSettings().setValue(kShownKey, true);
        hide();
    });
    setFixedWidth(680);
    fill();
}

bool GettingStarted::wasShown()
{
    return QSettings().value(kShownKey, false).toBool();
}

void GettingStarted::fill()
{
    const auto key = [](QAction* a) { return a->shortcut().toString(QKeySequence::NativeText).toHtmlEscaped(); };
    const QStringList pairs = KeyboardInput::pairNames();
    m_title->setText(tr("Getting started"));
    m_text->setText(
        "<p><b>" + tr("Run and pause") + "</b><br>" +
        tr("Simulation ▸ Run (%1) starts the machine, Pause (%2) holds it; Reset puts it back at the start.")
            .arg(key(m_run), key(m_pause)) +
        "</p><p><b>" + tr("Keys") + "</b><br>" +
        tr("Click the 3D view, then hold a key to open a valve: the first key of a pair (%1, %2, …) drives one way, the "
           "second the other. Simulation ▸ Keyboard Controls lists which drive each pair moves; in Train, the start "
           "screen and the attempt name the keys and levers of each stage.")
            .arg(pairs.value(0).toHtmlEscaped(), pairs.value(1).toHtmlEscaped()) +
        "</p><p><b>" + tr("Mouse in the 3D view") + "</b><br>" +
        tr("Left drag orbits, middle drag or Shift + left drag pans, the wheel zooms, a double click frames the model.") +
        "</p><p>" + tr("Help ▸ Getting Started shows this again.") + "</p>");
    m_close->setText(tr("Got it"));
    adjustSize();
}

void GettingStarted::open()
{
    fill();
    // over the middle of the window
    const QPoint centre = m_window->mapToGlobal(m_window->rect().center());
    move(centre - QPoint(width() / 2, height() / 2));
    show();
    raise();
}

void GettingStarted::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) fill();
    QFrame::changeEvent(event);
}

}  // namespace studio
