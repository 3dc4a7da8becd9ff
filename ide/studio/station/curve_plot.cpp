#include "ide/studio/station/curve_plot.h"

#include "ide/studio/station/channel_bars.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>

namespace studio {

CurvePlot::CurvePlot(QWidget* parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void CurvePlot::setCalibration(const trainer::ChannelCalibration& calibration)
{
    m_calibration = calibration;
    update();
}

void CurvePlot::setReading(double raw)
{
    if (raw == m_reading) return;
    m_reading = raw;
    update();
}

std::pair<double, double> CurvePlot::deadBand(const trainer::ChannelCalibration& c)
{
    return {c.rawCentre - c.deadBandLow * (c.rawCentre - c.rawMin),
            c.rawCentre + c.deadBandHigh * (c.rawMax - c.rawCentre)};
}

QSize CurvePlot::sizeHint() const
{
    return {340, 230};
}

QSize CurvePlot::minimumSizeHint() const
{
    return {220, 150};
}

void CurvePlot::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const trainer::ChannelCalibration& c = m_calibration;
    const QFontMetrics fm = fontMetrics();
    const int left = fm.horizontalAdvance(QStringLiteral("−1.0")) + 10;
    const int bottom = 2 * fm.height() + 6;
    const QRectF plot(left, 8, width() - left - 12, height() - bottom - 8);
    p.fillRect(rect(), palette().color(QPalette::Base));
    if (plot.width() < 20 || plot.height() < 20) return;
    if (!c.isValid()) {
        p.setPen(palette().color(QPalette::WindowText));
        p.drawText(plot, Qt::AlignCenter | Qt::TextWordWrap, c.problem());
        return;
    }

    const double lo = c.rawMin, hi = c.rawMax;
    auto xOf = [&](double raw) { return plot.left() + (raw - lo) / (hi - lo) * plot.width(); };
    auto yOf = [&](double u) { return plot.center().y() - u * plot.height() / 2.0; };

    // dead band
    const auto [bandLo, bandHi] = deadBand(c);
    if (bandHi > bandLo) {
        QColor shade = palette().color(QPalette::Mid);
        shade.setAlpha(70);
        p.fillRect(QRectF(QPointF(xOf(bandLo), plot.top()), QPointF(xOf(bandHi), plot.bottom())), shade);
    }

    // frame, zero line, centre line
    p.setPen(QPen(palette().color(QPalette::Mid), 1));
    p.setBrush(Qt::NoBrush);
    p.drawRect(plot);
    p.setPen(QPen(palette().color(QPalette::Mid), 1, Qt::DashLine));
    p.drawLine(QPointF(plot.left(), yOf(0)), QPointF(plot.right(), yOf(0)));
    p.drawLine(QPointF(xOf(c.rawCentre), plot.top()), QPointF(xOf(c.rawCentre), plot.bottom()));

    // the curve
    QPainterPath path;
    const int n = std::max(64, int(plot.width()));
    for (int i = 0; i <= n; ++i) {
        const double raw = lo + (hi - lo) * i / n;
        const QPointF pt(xOf(raw), yOf(c.apply(raw)));
        if (i == 0) path.moveTo(pt);
        else path.lineTo(pt);
    }
    p.setPen(QPen(QColor(0x1e, 0x88, 0xe5), 2));
    p.drawPath(path);

    // the live reading
    if (std::isfinite(m_reading)) {
        const double raw = std::clamp(m_reading, lo, hi);
        p.setPen(QPen(QColor(0xd8, 0x1b, 0x60), 1));
        p.drawLine(QPointF(xOf(raw), plot.top()), QPointF(xOf(raw), plot.bottom()));
        p.setBrush(QColor(0xd8, 0x1b, 0x60));
        p.drawEllipse(QPointF(xOf(raw), yOf(c.apply(raw))), 4, 4);
    }

    // labels
    p.setPen(palette().color(QPalette::WindowText));
    const double textH = fm.height();
    for (double u : {1.0, 0.0, -1.0}) {
        const QString s = u > 0 ? QStringLiteral("+1") : u < 0 ? QStringLiteral("−1") : QStringLiteral("0");
        p.drawText(QRectF(0, yOf(u) - textH / 2, left - 6, textH), Qt::AlignRight | Qt::AlignVCenter, s);
    }
    const double y = plot.bottom() + 2;
    p.drawText(QRectF(plot.left(), y, plot.width() / 3, textH), Qt::AlignLeft, formatRaw(lo));
    p.drawText(QRectF(plot.right() - plot.width() / 3, y, plot.width() / 3, textH), Qt::AlignRight, formatRaw(hi));
    const double xc = xOf(c.rawCentre);
    if (xc - plot.left() > plot.width() / 5 && plot.right() - xc > plot.width() / 5)
        p.drawText(QRectF(xc - 60, y, 120, textH), Qt::AlignHCenter, formatRaw(c.rawCentre));
    p.drawText(QRectF(plot.left(), y + textH, plot.width(), textH), Qt::AlignHCenter,
               tr("raw reading → output (shaded: dead band)"));
}

}  // namespace studio
