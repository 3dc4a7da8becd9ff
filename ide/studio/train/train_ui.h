#pragma once
// What the Train workspace's screens share: stars, numbers in the UI's locale, a
// word-wrapped label, and how a view frames the model with the targets.

#include <QString>

class QLabel;

namespace studio {

class Viewport;

namespace trainui {

/// ★★☆ for n of 3.
QString stars(int n);
/// `v` with `decimals` decimals in the UI's locale (1,5 in Spanish).
QString num(double v, int decimals);
/// A word-wrapped label.
QLabel* wrapped(const QString& text = {});
/// Fit All, then one notch of the wheel out: Fit All frames the model only, and the
/// targets (scene graphics) often lie just outside it.
void frameModelAndTargets(Viewport* v);

}  // namespace trainui
}  // namespace studio
