#pragma once
// padrob-studio --display-of STATION --view left|centre|right: a display node of the
// training centre (docs/studio.md "Training centre"). One window, one screen of a
// station's operator seat, drawn from the station's State stream alone: it joins the
// centre's DDS domain, announces itself as a display, and feeds what the station sends
// to a DisplayView. The bus is polled from a timer in the GUI thread (taking samples
// never blocks); a DDS error is shown in the window.

#include "ide/studio/centre/display_feed.h"
#include "ide/studio/centre/display_view.h"
#include "trainer/centre/bus.h"

#include <QWidget>

#include <memory>
#include <string>

class QTimer;

namespace studio {

class DisplayWindow : public QWidget {
    Q_OBJECT
public:
    /// Joins the centre on `bus` (its `reads` are set here) and shows `station`'s screen.
    /// With DDS Security (bus.securityDir) the node's identity is bus.node, by default
    /// defaultNodeName(station, screen).
    DisplayWindow(const QString& station, DisplayView::Screen screen, const trainer::centre::BusOptions& bus,
                  QWidget* parent = nullptr);
    ~DisplayWindow() override;

    DisplayView* view() const { return m_view; }
    const DisplayFeed& feed() const { return m_feed; }
    /// Why the window cannot join the centre (translated; "" when it did).
    QString busError() const { return m_busError; }

    /// "display-STATION-VIEW", made fit for a name in the centre's PKI.
    static QString defaultNodeName(const QString& station, DisplayView::Screen screen);

    /// --view's words: "left", "centre" (or "center"), "right". False for anything else.
    static bool parseScreen(const QString& word, DisplayView::Screen* screen);

    /// Takes what arrived on the bus (the timer calls it every few milliseconds).
    void poll();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();

    QString m_station;
    std::unique_ptr<trainer::centre::Bus> m_bus;
    std::string m_node;
    DisplayFeed m_feed;
    DisplayView* m_view;
    QTimer* m_poll;
    QString m_busError;
};

}  // namespace studio
