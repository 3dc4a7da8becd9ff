#include "ide/studio/train/train_ui.h"

#include "ide/studio/view/viewport.h"

#include <QCoreApplication>
#include <QLabel>
#include <QLocale>
#include <QWheelEvent>

namespace studio::trainui {

QString stars(int n)
{
    QString s;
    for (int i = 0; i < 3; ++i) s += i < n ? QChar(0x2605) : QChar(0x2606);
    return s;
}

QString num(double v, int decimals)
{
    return QLocale().toString(v, 'f', decimals);
}

QLabel* wrapped(const QString& text)
{
    auto* l = new QLabel(text);
    l->setWordWrap(true);
    return l;
}

void frameModelAndTargets(Viewport* v)
{
    v->fitAll();
    const QPointF centre(v->width() / 2.0, v->height() / 2.0);
    QWheelEvent out(centre, v->mapToGlobal(centre), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier,
                    Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(v, &out);
}

}  // namespace studio::trainui
