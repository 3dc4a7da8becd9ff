#include "ide/studio/train/lever_bars.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace studio {

namespace {
constexpr int kRowHeight = 36;  // [px] a label over a bar
constexpr int kWidth = 320;
constexpr int kMargin = 10;
}  // namespace

LeverBars::LeverBars(QWidget* parent) : QWidget(parent)
{
    setObjectName("LeverBars");
    setAttribute(Qt::WA_TransparentForMouseEvents);
    hide();
}

void LeverBars::setDrives(const QList<DriveControls>& drives)
{
    m_rows.clear();
    for (const DriveControls& d : drives) {
        const QString control = d.controls.isEmpty() ? QString() : d.controls.first();
        m_rows.push_back({d.drive.treeJoint, control.isEmpty() ? d.drive.label() : control + QStringLiteral(" — ") + d.drive.label(), 0.0});
    }
    setFixedSize(sizeHint());
    update();
}

void LeverBars::setCommands(const Eigen::VectorXd& u)
{
    bool changed = false;
    for (Row& r : m_rows) {
        const double v = r.treeJoint >= 0 && r.treeJoint < u.size() ? std::clamp(u[r.treeJoint], -1.0, 1.0) : 0.0;
        changed = changed || std::abs(v - r.u) > 1e-3;
        r.u = v;
    }
    if (changed) update();
}

double LeverBars::command(int row) const
{
    return row >= 0 && row < rows() ? m_rows[std::size_t(row)].u : 0.0;
}

QString LeverBars::label(int row) const
{
    return row >= 0 && row < rows() ? m_rows[std::size_t(row)].label : QString();
}

QSize LeverBars::sizeHint() const
{
    return {kWidth, 2 * kMargin + kRowHeight * std::max(1, rows())};
}

void LeverBars::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(20, 24, 28, 200));
    p.drawRoundedRect(rect(), 8, 8);
    QFont f = font();
    f.setPixelSize(13);
    p.setFont(f);
    const int barWidth = width() - 2 * kMargin;
    for (int i = 0; i < rows(); ++i) {
        const Row& r = m_rows[std::size_t(i)];
        const int y = kMargin + i * kRowHeight;
        p.setPen(Qt::white);
        p.drawText(QRect(kMargin, y, barWidth, 16), Qt::AlignLeft | Qt::AlignVCenter,
                   p.fontMetrics().elidedText(r.label, Qt::ElideRight, barWidth));
        // the bar: its track, the centre, the command from the centre
        const QRect track(kMargin, y + 19, barWidth, 10);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(255, 255, 255, 45));
        p.drawRoundedRect(track, 4, 4);
        const int centre = track.center().x();
        const int reach = int(std::lround(r.u * track.width() / 2.0));
        p.setBrush(r.u >= 0 ? QColor("#4cd964") : QColor("#ffb340"));
        p.drawRect(QRect(std::min(centre, centre + reach), track.top(), std::abs(reach), track.height()));
        p.setBrush(Qt::white);
        p.drawRect(QRect(centre - 1, track.top() - 2, 2, track.height() + 4));
    }
}

}  // namespace studio
