#include "ide/studio/sim/hydraulic_panel.h"

#include "ide/studio/sim/simulation_runner.h"

#include <QEvent>
#include <QHelpEvent>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QResizeEvent>
#include <QScrollArea>
#include <QTimer>
#include <QToolTip>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace studio {

namespace {

constexpr int kMargin = 6;  // [px] around the bars
constexpr int kGap = 6;     // [px] between columns
const QColor kPressureFill(0x90, 0xc2, 0xf0);
const QColor kReliefFill(0xef, 0x53, 0x50);
const QColor kFlowFill(0xa5, 0xd6, 0xa7);
const QColor kSaturatedFill(0xff, 0xb7, 0x4d);
const QColor kSpoolFill(0xb0, 0xbe, 0xc5);
const QColor kCavitation(0x8e, 0x24, 0xaa);

/// The locale's numbers without group separators.
QLocale numbers()
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale;
}

/// A pressure [Pa] in MPa, one decimal: "12,5".
QString mpa(double pa) { return numbers().toString(pa / 1e6, 'f', 1); }
/// A flow [m^3/s] in L/min, one decimal: "66,6".
QString lpm(double flow) { return numbers().toString(flow * 60000.0, 'f', 1); }
/// A spool position x ∈ [−1, 1] in % with its sign: "+45", "−12", "0".
QString percent(double x)
{
    const long v = std::lround(std::clamp(x, -1.0, 1.0) * 100.0);
    const QString digits = numbers().toString(qlonglong(std::abs(v)));
    return v == 0 ? digits : (v > 0 ? QStringLiteral("+") : QStringLiteral("−")) + digits;
}

/// One bar: a box filled between two fractions of its width, with a text in the middle.
struct Bar {
    QRectF box;
    double from = 0, to = 0;  ///< the filled part, as fractions of the width (either order)
    QColor fill;
    bool hatch = false;       ///< hatched over (cavitation)
    bool centreTick = false;  ///< a tick at the middle (the spool's rest)
    QStringList texts;        ///< the first that fits is written (else the last, elided)
};

void drawBar(QPainter& p, const QPalette& palette, const Bar& bar)
{
    const QRectF r = bar.box.adjusted(0.5, 2.5, -0.5, -2.5);
    p.setPen(palette.color(QPalette::Mid));
    p.setBrush(palette.color(QPalette::Base));
    p.drawRect(r);
    const double from = std::clamp(std::min(bar.from, bar.to), 0.0, 1.0);
    const double to = std::clamp(std::max(bar.from, bar.to), 0.0, 1.0);
    const QRectF filled(r.left() + from * r.width(), r.top() + 0.5, (to - from) * r.width(), r.height() - 0.5);
    if (filled.width() >= 1.0) p.fillRect(filled, bar.fill);  // (not a hairline for a value near the origin)
    if (bar.hatch) p.fillRect(r, QBrush(kCavitation, Qt::BDiagPattern));
    if (bar.centreTick) {  // (notches outside the border, clear of the text)
        const double x = r.center().x();
        p.setPen(QPen(palette.color(QPalette::WindowText), 1));
        p.drawLine(QPointF(x, r.top() - 2.5), QPointF(x, r.top()));
        p.drawLine(QPointF(x, r.bottom()), QPointF(x, r.bottom() + 2.5));
    }
    const QFontMetrics fm = p.fontMetrics();
    const int room = int(r.width()) - 6;
    QString text;
    for (const QString& t : bar.texts) {
        if (fm.horizontalAdvance(t) <= room) {
            text = t;
            break;
        }
    }
    if (text.isEmpty() && !bar.texts.isEmpty()) text = fm.elidedText(bar.texts.back(), Qt::ElideRight, room);
    p.setPen(palette.color(QPalette::Text));
    p.drawText(r, Qt::AlignCenter, text);
}

/// A left-aligned text in `r`, elided to fit.
void drawLabel(QPainter& p, const QRectF& r, const QString& text, const QColor& colour)
{
    p.setPen(colour);
    p.drawText(r, Qt::AlignLeft | Qt::AlignVCenter, p.fontMetrics().elidedText(text, Qt::ElideRight, int(r.width())));
}

}  // namespace

// ---- the canvas: paints what the panel computes ---------------------------------

class HydraulicPanel::Canvas : public QWidget {
public:
    explicit Canvas(HydraulicPanel* panel) : m_panel(panel) {}

protected:
    void paintEvent(QPaintEvent*) override
    {
        QPainter p(this);
        m_panel->paintCanvas(p, width(), height());
    }
    void resizeEvent(QResizeEvent* event) override
    {
        QWidget::resizeEvent(event);
        if (event->size().width() != event->oldSize().width()) m_panel->relayout();
    }
    bool event(QEvent* event) override
    {
        if (event->type() == QEvent::ToolTip) {
            auto* help = static_cast<QHelpEvent*>(event);
            const QString text = m_panel->toolTipAt(help->pos());
            if (text.isEmpty()) {
                QToolTip::hideText();
                event->ignore();
            } else {
                QToolTip::showText(help->globalPos(), text, this);
            }
            return true;
        }
        return QWidget::event(event);
    }

private:
    HydraulicPanel* m_panel;
};

// ---- the panel ------------------------------------------------------------------

HydraulicPanel::HydraulicPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_heading = new QLabel(this);
    m_heading->setObjectName("HydraulicsHeading");
    m_heading->setContentsMargins(kMargin, kMargin, kMargin, 0);
    QFont bold = m_heading->font();
    bold.setBold(true);
    m_heading->setFont(bold);
    m_heading->hide();
    layout->addWidget(m_heading);
    m_scroll = new QScrollArea(this);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_canvas = new Canvas(this);
    m_canvas->setObjectName("HydraulicsCanvas");
    m_scroll->setWidget(m_canvas);
    layout->addWidget(m_scroll, 1);

    m_pollTimer = new QTimer(this);
    m_pollTimer->setInterval(16);
    connect(m_pollTimer, &QTimer::timeout, this, &HydraulicPanel::poll);
    m_heading->setText(tr("Hydraulics"));
}

HydraulicPanel::~HydraulicPanel() = default;

void HydraulicPanel::setRunner(SimulationRunner* runner)
{
    m_runner = runner;
    if (runner) m_pollTimer->start();
    else m_pollTimer->stop();
}

void HydraulicPanel::poll()
{
    if (!m_runner) return;
    std::shared_ptr<const Snapshot> s = m_runner->latest();
    if (s == m_snapshot) return;
    // hidden, only a new model matters (the window may show the panel for it)
    const bool newModel = (s ? s->bundle : nullptr) != m_bundle;
    if (newModel || isVisible()) setSnapshot(std::move(s));
}

void HydraulicPanel::setSnapshot(std::shared_ptr<const Snapshot> snapshot)
{
    m_snapshot = std::move(snapshot);
    std::shared_ptr<const ModelBundle> bundle = m_snapshot ? m_snapshot->bundle : nullptr;
    if (bundle != m_bundle || !m_announced) {
        m_bundle = std::move(bundle);
        m_announced = true;
        relabel();
        relayout();
        emit modelChanged(hasFluidPower());
    }
    m_canvas->update();
}

void HydraulicPanel::setHeadingVisible(bool visible) { m_heading->setVisible(visible); }

void HydraulicPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        m_heading->setText(tr("Hydraulics"));
        relabel();
        relayout();
        m_canvas->update();
    }
    QWidget::changeEvent(event);
}

void HydraulicPanel::relabel()
{
    m_pumpLabels.clear();
    m_sectionLabels.clear();
    if (!m_bundle || !m_bundle->model) return;
    const solver::Model& m = *m_bundle->model;
    for (const solver::CompiledPump& pump : m.pumps) {
        const QString name = QString::fromStdString(pump.name);
        m_pumpLabels << (name.isEmpty() ? tr("Pump %1").arg(pump.id) : tr("Pump %1: %2").arg(pump.id).arg(name));
    }
    for (const solver::CompiledCircuit& c : m.circuits) {
        const auto j = std::size_t(c.joint);
        const QString name = QString::fromStdString(m.jointName[j]);
        m_sectionLabels << (name.isEmpty() ? tr("C %1").arg(m.jointId[j]) : tr("C %1 %2").arg(m.jointId[j]).arg(name));
    }
}

QString HydraulicPanel::pumpLabel(int p) const { return m_pumpLabels.value(p); }
QString HydraulicPanel::sectionLabel(int c) const { return m_sectionLabels.value(c); }

QString HydraulicPanel::pumpSummary(int p) const
{
    if (!m_snapshot || p < 0 || std::size_t(p) >= m_snapshot->pumps.size()) return {};
    const PumpSnapshot& s = m_snapshot->pumps[std::size_t(p)];
    QStringList lines{pumpLabel(p), tr("Supply pressure: %1 of %2 MPa").arg(mpa(s.supplyPressure), mpa(s.pmax)),
                      tr("Delivered flow: %1 of %2 L/min").arg(lpm(s.flow), lpm(s.qmax)),
                      tr("Demand of the open sections: %1 L/min").arg(lpm(s.demand))};
    if (s.saturated()) lines << tr("Saturated: the sections want more flow than the pump gives.");
    return lines.join(QLatin1Char('\n'));
}

QString HydraulicPanel::sectionSummary(int c) const
{
    if (!m_snapshot || c < 0 || std::size_t(c) >= m_snapshot->circuits.size()) return {};
    const CircuitSnapshot& s = m_snapshot->circuits[std::size_t(c)];
    QStringList lines{sectionLabel(c), tr("Spool: %1 %").arg(percent(s.spool)),
                      tr("Chamber A: %1 MPa, flow in %2 L/min").arg(mpa(s.pressureA), lpm(s.flowA)),
                      tr("Chamber B: %1 MPa, flow in %2 L/min").arg(mpa(s.pressureB), lpm(s.flowB)),
                      tr("Relief setting: %1 MPa").arg(mpa(s.relief))};
    if (s.pressureA >= kReliefShare * s.relief) lines << tr("Chamber A is at the relief setting.");
    if (s.pressureB >= kReliefShare * s.relief) lines << tr("Chamber B is at the relief setting.");
    if (s.cavitation & 1) lines << tr("Chamber A cavitates.");
    if (s.cavitation & 2) lines << tr("Chamber B cavitates.");
    return lines.join(QLatin1Char('\n'));
}

QString HydraulicPanel::toolTipAt(const QPoint& pos) const
{
    for (const auto& [rect, index] : m_hits) {
        if (rect.contains(pos)) return index < 0 ? pumpSummary(-1 - index) : sectionSummary(index);
    }
    return {};
}

QSize HydraulicPanel::sizeHint() const
{
    // narrow enough for the Train workspace's side panel, wide enough for its bars
    const QFontMetrics fm = fontMetrics();
    return {fm.horizontalAdvance(QLatin1Char('0')) * 36, fm.height() * 24};
}

int HydraulicPanel::labelColumn(const QFontMetrics& fm) const
{
    int width = 0;
    for (const QString& s : m_sectionLabels) width = std::max(width, fm.horizontalAdvance(s));
    return width + 2 + kGap;  // (2 px of slack: elidedText measures in fractions)
}

HydraulicPanel::Layout HydraulicPanel::layoutFor(int width, int height) const
{
    Layout l;
    if (!hasFluidPower()) return l;
    const QFontMetrics fm = fontMetrics();
    // wide: the sections' joints whole at the left, and three bars that hold "00,0 MPa"
    const int bar = fm.horizontalAdvance(QStringLiteral("00,0 MPa")) + 12;
    l.wide = width - 2 * kMargin >= labelColumn(fm) + 3 * bar + 2 * kGap;
    const int pumps = int(m_snapshot->pumps.size()), sections = int(m_snapshot->circuits.size());
    // in half rows: each pump's name and bars, half a row of space, the sections' header and rows
    l.rows2 = 2 * (l.wide ? 2 : 3) * pumps + (sections > 0 ? 1 + 2 * (1 + (l.wide ? 1 : 2) * sections) : 0);
    const int least = fm.height() + 2, most = fm.height() + 12;
    l.row = std::clamp(2 * (height - 2 * kMargin) / std::max(1, l.rows2), least, most);
    return l;
}

void HydraulicPanel::relayout()
{
    const Layout l = layoutFor(m_canvas->width(), 0);  // (the least row height)
    m_canvas->setMinimumHeight(hasFluidPower() ? l.rows2 * l.row / 2 + 2 * kMargin : 0);
}

void HydraulicPanel::paintCanvas(QPainter& p, int width, int height)
{
    m_hits.clear();
    const QPalette& palette = m_canvas->palette();
    if (!hasFluidPower()) {
        p.setPen(palette.color(QPalette::PlaceholderText));
        const QString note = m_snapshot ? tr("This model has no fluid-power drives.") : tr("No model is running.");
        p.drawText(QRect(kMargin, kMargin, width - 2 * kMargin, height - 2 * kMargin),
                   Qt::AlignCenter | Qt::TextWordWrap, note);
        return;
    }
    const Snapshot& s = *m_snapshot;
    const Layout l = layoutFor(width, height);
    const QFontMetrics fm = p.fontMetrics();
    const int inner = width - 2 * kMargin;
    const int labelWidth = l.wide ? labelColumn(fm) : 0;
    const int x0 = kMargin + labelWidth, room = inner - labelWidth;
    const QColor text = palette.color(QPalette::Text), dim = palette.color(QPalette::PlaceholderText);
    int y = kMargin;

    // pumps: the name, then the supply pressure against p_max and the flow against Qmax
    // (side by side when wide, one under the other when narrow)
    const int half = (inner - kGap) / 2;
    for (std::size_t k = 0; k < s.pumps.size(); ++k) {
        const PumpSnapshot& pump = s.pumps[k];
        const int top = y;
        drawLabel(p, QRectF(kMargin, y, inner, l.row), pumpLabel(int(k)), text);
        y += l.row;
        const QRect supply = l.wide ? QRect(kMargin, y, half, l.row) : QRect(kMargin, y, inner, l.row);
        const QRect flow = l.wide ? QRect(kMargin + half + kGap, y, inner - half - kGap, l.row)
                                  : QRect(kMargin, y + l.row, inner, l.row);
        y += l.wide ? l.row : 2 * l.row;
        const QString pS = mpa(pump.supplyPressure), qP = lpm(pump.flow);
        const bool cutOff = pump.supplyPressure >= kReliefShare * pump.pmax;
        drawBar(p, palette,
                {supply, 0, pump.pmax > 0 ? pump.supplyPressure / pump.pmax : 0, cutOff ? kReliefFill : kPressureFill,
                 false, false, {tr("supply %1 of %2 MPa").arg(pS, mpa(pump.pmax)), tr("%1 MPa").arg(pS)}});
        const QStringList flowTexts =
            pump.saturated() ? QStringList{tr("flow %1 of %2 L/min, saturated").arg(qP, lpm(pump.qmax)),
                                           tr("%1 L/min, saturated").arg(qP), tr("saturated")}
                             : QStringList{tr("flow %1 of %2 L/min").arg(qP, lpm(pump.qmax)), tr("%1 L/min").arg(qP)};
        drawBar(p, palette,
                {flow, 0, pump.qmax > 0 ? pump.flow / pump.qmax : 0, pump.saturated() ? kSaturatedFill : kFlowFill,
                 false, false, flowTexts});
        m_hits.emplace_back(QRect(0, top, width, y - top), -1 - int(k));
    }
    if (s.circuits.empty()) return;
    y += l.row / 2;

    // the sections: the header, then the spool from the centre and both chambers
    const QString heads[3] = {tr("Spool"), tr("Chamber A"), tr("Chamber B")};
    // (wide enough for its heading, in any language, up to 40 %)
    const int spoolWidth = std::min(std::max((room - 2 * kGap) * 28 / 100, fm.horizontalAdvance(heads[0]) + 8),
                                    (room - 2 * kGap) * 40 / 100);
    const int chamberWidth = (room - 2 * kGap - spoolWidth) / 2;
    const int columns[3] = {x0, x0 + spoolWidth + kGap, x0 + spoolWidth + chamberWidth + 2 * kGap};
    const int widths[3] = {spoolWidth, chamberWidth, chamberWidth};
    if (l.wide) drawLabel(p, QRectF(kMargin, y, labelWidth - kGap, l.row), tr("Valve section"), dim);
    p.setPen(dim);
    for (int i = 0; i < 3; ++i) {
        const QRect head(columns[i], y, widths[i], l.row);
        p.drawText(head, Qt::AlignCenter, fm.elidedText(heads[i], Qt::ElideRight, head.width()));
    }
    y += l.row;
    for (std::size_t c = 0; c < s.circuits.size(); ++c) {
        const CircuitSnapshot& k = s.circuits[c];
        const int top = y;
        drawLabel(p, QRectF(kMargin, y, l.wide ? labelWidth - kGap : inner, l.row), sectionLabel(int(c)), text);
        if (!l.wide) y += l.row;
        auto at = [&](int column) { return QRectF(columns[column], y, widths[column], l.row); };
        drawBar(p, palette, {at(0), 0.5, 0.5 + 0.5 * k.spool, kSpoolFill, false, true, {tr("%1 %").arg(percent(k.spool))}});
        const double pressures[2] = {k.pressureA, k.pressureB};
        for (int side = 0; side < 2; ++side) {
            const double pa = pressures[side];
            const bool relief = k.relief > 0 && pa >= kReliefShare * k.relief;
            const bool cavitates = (k.cavitation & (1 << side)) != 0;
            const QStringList texts = cavitates ? QStringList{tr("%1 MPa, cavitation").arg(mpa(pa)), tr("cavitation")}
                                      : relief  ? QStringList{tr("%1 MPa, relief").arg(mpa(pa)), tr("%1 MPa").arg(mpa(pa))}
                                                : QStringList{tr("%1 MPa").arg(mpa(pa))};
            drawBar(p, palette, {at(1 + side), 0, k.relief > 0 ? pa / k.relief : 0, relief ? kReliefFill : kPressureFill,
                                 cavitates, false, texts});
        }
        y += l.row;
        m_hits.emplace_back(QRect(0, top, width, y - top), int(c));
    }
}

}  // namespace studio
