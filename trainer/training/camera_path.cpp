#include "trainer/training/camera_path.h"

#include "trainer/io/read_file.h"

#include "solver/core/output_file.h"

#include <QCoreApplication>
#include <QFile>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trainer {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(CameraPath)
};

constexpr const char* kHeader = "# padrob camera path 1";

}  // namespace

bool CameraPath::load(const QString& path, CameraPath& out, QString* error)
{
    const std::optional<QByteArray> text =
        readLimitedFile(path, kMaxCameraPathBytes, solver::trText("Tutorials", "a camera path"), ".cam",
                        solver::trText("Tutorials", "a camera path is a text file that padrob writes while a demonstration is recorded; check that this is one"), error);
    if (!text || !parse(*text, out, error)) {
        if (error) *error = path + ": " + *error;  // every reason names the file
        return false;
    }
    return true;
}

bool CameraPath::parse(const QByteArray& text, CameraPath& out, QString* error)
{
    CameraPath p;
    const QList<QByteArray> lines = text.split('\n');
    bool headerSeen = false;
    for (qsizetype n = 0; n < lines.size(); ++n) {
        const QByteArray line = lines[n].trimmed();
        auto fail = [&](const QString& why) {
            if (error) *error = Tr::tr("line %1: %2").arg(n + 1).arg(why);
            return false;
        };
        if (line.startsWith(kHeader)) {
            headerSeen = true;
            continue;
        }
        if (line.isEmpty() || line.startsWith('#')) continue;
        if (!headerSeen) return fail(Tr::tr("not a camera path (the first line must be \"%1\")").arg(kHeader));
        const QList<QByteArray> f = line.simplified().split(' ');
        if (f.size() != 7) return fail(Tr::tr("expected 7 numbers (t, target x y z, distance, yaw, pitch), found %1").arg(f.size()));
        double v[7];
        for (int i = 0; i < 7; ++i) {
            bool ok = false;
            v[i] = f[i].toDouble(&ok);
            if (!ok || !std::isfinite(v[i])) return fail(Tr::tr("\"%1\" is not a number").arg(QString::fromUtf8(f[i])));
        }
        if (!p.m_keys.empty() && v[0] < p.m_keys.back().t) return fail(Tr::tr("the time goes back"));
        if (v[4] <= 0) return fail(Tr::tr("the distance must be greater than 0"));
        if (std::abs(v[6]) > std::numbers::pi / 2) return fail(Tr::tr("the pitch must be within ±π/2"));
        p.add({v[0], {v[1], v[2], v[3]}, v[4], v[5], v[6]});
    }
    if (!headerSeen) {
        if (error) *error = Tr::tr("not a camera path (the first line must be \"%1\")").arg(kHeader);
        return false;
    }
    out = std::move(p);
    return true;
}

bool CameraPath::save(const QString& path, QString* error) const
{
    QByteArray text = QByteArray(kHeader) + "\n# t  target_x target_y target_z  distance  yaw  pitch\n";
    for (const CameraKey& k : m_keys) {
        text += QByteArray::number(k.t, 'f', 3);
        for (double v : {k.target.x(), k.target.y(), k.target.z(), k.distance, k.yaw, k.pitch}) {
            text += ' ';
            text += QByteArray::number(v, 'g', 9);
        }
        text += '\n';
    }
    // replaced whole, on the disk, or left as it was (solver/core/output_file.h)
    solver::Text writeError;
    if (!solver::writeWholeFile(path.toStdString(), text.toStdString(), {}, writeError)) {
        if (error) *error = translated(writeError);
        return false;
    }
    return true;
}

void CameraPath::add(const CameraKey& key)
{
    if (!m_keys.empty() && key.t <= m_keys.back().t) m_keys.back() = key;
    else m_keys.push_back(key);
}

CameraKey CameraPath::at(double t) const
{
    if (m_keys.empty()) return {};
    if (t <= m_keys.front().t) return m_keys.front();
    if (t >= m_keys.back().t) return m_keys.back();
    const auto next = std::upper_bound(m_keys.begin(), m_keys.end(), t, [](double x, const CameraKey& k) { return x < k.t; });
    const CameraKey& b = *next;
    const CameraKey& a = *(next - 1);
    const double s = b.t > a.t ? (t - a.t) / (b.t - a.t) : 1.0;
    CameraKey k;
    k.t = t;
    k.target = a.target + s * (b.target - a.target);
    k.distance = a.distance + s * (b.distance - a.distance);
    double dyaw = std::remainder(b.yaw - a.yaw, 2 * std::numbers::pi);  // the short way round
    k.yaw = a.yaw + s * dyaw;
    k.pitch = a.pitch + s * (b.pitch - a.pitch);
    return k;
}

}  // namespace trainer
