#include "ide/studio/centre/display_window.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QEvent>
#include <QSysInfo>
#include <QTimer>
#include <QVBoxLayout>

namespace studio {

namespace centre = trainer::centre;

DisplayWindow::DisplayWindow(const QString& station, DisplayView::Screen screen, const centre::BusOptions& bus,
                             QWidget* parent)
    : QWidget(parent), m_station(station), m_feed(station.toStdString()), m_view(new DisplayView(&m_feed, screen, this)),
      m_poll(new QTimer(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_view);
    retranslate();

    centre::BusOptions o = bus;
    o.reads = centre::TopicAnnounce | centre::TopicState;
    if (o.node.isEmpty()) o.node = defaultNodeName(station, screen);
    if (!o.key.isSet()) {
        // nothing a station sends can be checked without the key: nothing is drawn
        m_busError = tr("This display has no centre key (--centre-key FILE): it cannot check what the stations send, "
                        "so it shows nothing.");
        m_view->setProblem(m_busError);
        return;
    }
    if (!o.key.mayServe(station.toStdString(), QString(), nullptr)) {
        // a station's key checks only that station's messages
        m_busError = tr("This display's key is station %1's: it cannot check what station %2 sends, so it shows "
                        "nothing. Give it station %2's key or the centre's key.")
                         .arg(QString::fromStdString(o.key.node()), station);
        m_view->setProblem(m_busError);
        return;
    }
    QString error;
    m_bus = centre::Bus::open(o, &error);
    if (!m_bus) {
        m_busError = tr("This display cannot join the training centre's network (DDS domain %1): %2")
                         .arg(bus.domain)
                         .arg(error);
        m_view->setProblem(m_busError);
        return;
    }
    // a display says who it is, so the centre's list can name it
    static const char* const kSides[] = {"left", "centre", "right"};
    centre::Announce a;
    a.node = "display:" + station.toStdString() + ":" + kSides[int(screen)] + "@" +
             QSysInfo::machineHostName().toStdString() + ":" + std::to_string(QCoreApplication::applicationPid());
    if (a.node.size() > centre::limits::kName) a.node = a.node.substr(a.node.size() - centre::limits::kName);
    a.role = "display";
    a.host = QSysInfo::machineHostName().toStdString();
    a.pid = static_cast<int>(QCoreApplication::applicationPid());
    a.startedMs = static_cast<std::uint64_t>(QDateTime::currentMSecsSinceEpoch());
    m_node = a.node;
    m_bus->announce(a);
    m_poll->setTimerType(Qt::PreciseTimer);
    connect(m_poll, &QTimer::timeout, this, &DisplayWindow::poll);
    m_poll->start(4);  // states come at 60 Hz: none is missed, none waits long
}

DisplayWindow::~DisplayWindow()
{
    if (m_bus && !m_node.empty()) m_bus->withdraw(m_node);
}

QString DisplayWindow::defaultNodeName(const QString& station, DisplayView::Screen screen)
{
    static const char* const kSides[] = {"left", "centre", "right"};
    QString name = QStringLiteral("display-%1-%2").arg(station, QLatin1String(kSides[int(screen)]));
    // a name the centre's PKI takes (letters, digits, - _ . @): anything else becomes '_'
    for (QChar& c : name)
        if (!(c.isLetterOrNumber() && c.unicode() < 128) && c != '-' && c != '_' && c != '.' && c != '@') c = '_';
    return name.left(64);
}

bool DisplayWindow::parseScreen(const QString& word, DisplayView::Screen* screen)
{
    const QString w = word.trimmed().toLower();
    if (w == QLatin1String("left")) *screen = DisplayView::Left;
    else if (w == QLatin1String("centre") || w == QLatin1String("center")) *screen = DisplayView::Centre;
    else if (w == QLatin1String("right")) *screen = DisplayView::Right;
    else return false;
    return true;
}

void DisplayWindow::poll()
{
    if (!m_bus) return;
    const double now = centreClock();
    for (const centre::Bus::Seen& s : m_bus->takeAnnounces()) {
        if (s.gone) {
            // withdrawn: "left"; its writer gone (killed): the silence shows it
            if (s.withdrew) m_feed.withdraw(s.announce.node);
        } else {
            m_feed.announce(s.announce);
        }
    }
    for (const centre::State& s : m_bus->takeStates()) m_feed.push(s, now);
}

void DisplayWindow::retranslate()
{
    static const char* const kSides[] = {QT_TR_NOOP("left screen"), QT_TR_NOOP("centre screen"),
                                         QT_TR_NOOP("right screen")};
    setWindowTitle(tr("Padrob display: station %1, %2").arg(m_station, tr(kSides[int(m_view->side())])));
}

void DisplayWindow::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange) retranslate();
}

}  // namespace studio
