#pragma once
// The camera of a demonstration: where the expert's viewer looked while the run was
// recorded, replayed with it (docs/training.md "Demonstrations"). An orbit camera (a
// target point, a distance, yaw and pitch) at key times, interpolated linearly (yaw the
// short way round). Text, one key per line, '#' comments:
//
//   # padrob camera path 1
//   # t  target_x target_y target_z  distance  yaw  pitch      [s, m, m, m, m, rad, rad]
//   0.0  1.2 2.0 0.5  9.0  -1.0  0.45

#include <Eigen/Core>

#include <QString>

#include <vector>

namespace trainer {

struct CameraKey {
    double t = 0.0;
    Eigen::Vector3d target = Eigen::Vector3d::Zero();
    double distance = 10.0;
    double yaw = 0.0;
    double pitch = 0.0;
};

class CameraPath {
public:
    /// Reads a camera path (a regular file, at most kMaxCameraPathBytes). False with `error`
    /// ("x.cam: line 4: …", translated); `out` is then untouched.
    static bool load(const QString& path, CameraPath& out, QString* error);
    static bool parse(const QByteArray& text, CameraPath& out, QString* error);
    /// Writes it (solver::writeWholeFile: whole and on the disk, or not at all). False with `error`.
    bool save(const QString& path, QString* error) const;

    /// Adds a key (times must not go back; a key at the same time replaces the last).
    void add(const CameraKey& key);
    bool empty() const { return m_keys.empty(); }
    const std::vector<CameraKey>& keys() const { return m_keys; }
    double duration() const { return m_keys.empty() ? 0.0 : m_keys.back().t; }
    /// The camera at time t (held before the first key and after the last).
    CameraKey at(double t) const;

private:
    std::vector<CameraKey> m_keys;
};

}  // namespace trainer
