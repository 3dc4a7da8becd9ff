#include "ide/studio/editor/diagnostic_text.h"

#include "ide/i18n/diagnostic_text.h"

#include <QCoreApplication>
#include <QPainter>
#include <QPixmap>

namespace studio {

namespace {

// the translation context of the texts below (lupdate reads Diagnostics::tr)
struct Diagnostics {
    Q_DECLARE_TR_FUNCTIONS(Diagnostics)
};

}  // namespace

QString severityText(solver::Severity severity)
{
    switch (severity) {
    case solver::Severity::Error: return Diagnostics::tr("Error");
    case solver::Severity::Warning: return Diagnostics::tr("Warning");
    case solver::Severity::Note: return Diagnostics::tr("Note");
    }
    return Diagnostics::tr("Error");
}

QColor severityColor(solver::Severity severity)
{
    switch (severity) {
    case solver::Severity::Error: return QColor(0xd3, 0x2f, 0x2f);
    case solver::Severity::Warning: return QColor(0xe6, 0x9a, 0x00);
    case solver::Severity::Note: return QColor(0x19, 0x76, 0xd2);
    }
    return QColor(0xd3, 0x2f, 0x2f);
}

namespace {

QIcon drawSeverityIcon(solver::Severity severity)
{
    QIcon icon;
    for (int size : {16, 32}) {
        QPixmap pm(size, size);
        pm.fill(Qt::transparent);
        QPainter p(&pm);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(Qt::NoPen);
        p.setBrush(severityColor(severity));
        const qreal m = size * 0.1;
        p.drawEllipse(QRectF(m, m, size - 2 * m, size - 2 * m));
        // "!" for errors and warnings, "i" for notes
        p.setPen(QPen(Qt::white, size * 0.12, Qt::SolidLine, Qt::RoundCap));
        const qreal cx = size / 2.0;
        if (severity == solver::Severity::Note) {
            p.drawPoint(QPointF(cx, size * 0.3));
            p.drawLine(QPointF(cx, size * 0.45), QPointF(cx, size * 0.72));
        } else {
            p.drawLine(QPointF(cx, size * 0.27), QPointF(cx, size * 0.55));
            p.drawPoint(QPointF(cx, size * 0.72));
        }
        p.end();
        icon.addPixmap(pm);
    }
    return icon;
}

}  // namespace

QIcon severityIcon(solver::Severity severity)
{
    // drawn once (a junk file lists 10,000 problems)
    static const QIcon icons[3] = {drawSeverityIcon(solver::Severity::Error), drawSeverityIcon(solver::Severity::Warning),
                                   drawSeverityIcon(solver::Severity::Note)};
    switch (severity) {
    case solver::Severity::Error: return icons[0];
    case solver::Severity::Warning: return icons[1];
    case solver::Severity::Note: return icons[2];
    }
    return icons[0];
}

QString diagnosticMessage(const solver::Diagnostic& d) { return i18n::message(d); }

QString diagnosticHint(const solver::Diagnostic& d) { return i18n::hint(d); }

QString diagnosticLocation(const solver::Diagnostic& d)
{
    if (!d.pos.valid()) return QString();
    return QStringLiteral("%1:%2").arg(d.pos.line).arg(d.pos.column);
}

QString diagnosticToolTip(const solver::Diagnostic& d)
{
    QString html = QStringLiteral("<p style='white-space:nowrap'><b style='color:%1'>%2</b>: %3")
                       .arg(severityColor(d.severity).name(), severityText(d.severity).toHtmlEscaped(),
                            diagnosticMessage(d).toHtmlEscaped());
    const QString hint = diagnosticHint(d);
    if (!hint.isEmpty()) html += QStringLiteral("<br><i>%1</i> %2").arg(Diagnostics::tr("Hint:").toHtmlEscaped(), hint.toHtmlEscaped());
    html += QStringLiteral("<br><small>[%1]</small></p>").arg(QString::fromStdString(d.code).toHtmlEscaped());
    return html;
}

}  // namespace studio
