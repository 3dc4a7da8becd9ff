// Tests of the 3D viewport (ide/studio/view): real windows on an X server (xcb), images
// read back with grabFramebuffer() and saved as PNGs in PADROB_SCREENSHOT_DIR (view_*.png).
#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/snapshot.h"
#include "ide/studio/view/camera.h"
#include "ide/studio/view/mesh_builder.h"
#include "ide/studio/view/scene_file.h"
#include "ide/studio/view/scene_geometry.h"
#include "ide/studio/view/viewport.h"
#include "ide/studio/view/viewport_layout.h"

#include "solver/core/data.h"
#include "solver/core/state.h"
#include "solver/integrate/simulation.h"
#include "solver/kinematics/kinematics.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QImage>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QSet>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QWheelEvent>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

using studio::DisplayMode;
using studio::Viewport;

namespace {

QString screenshotDir()
{
    return QStringLiteral(PADROB_SCREENSHOT_DIR);
}

void save(const QImage& image, const QString& name)
{
    QDir().mkpath(screenshotDir());
    image.save(screenshotDir() + QStringLiteral("/view_") + name + QStringLiteral(".png"));
}

std::shared_ptr<const studio::ModelBundle> bundleFromFile(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return nullptr;
    solver::Diagnostics diags(path.toStdString());
    return studio::makeBundle(QString::fromUtf8(f.readAll()), path, diags);
}

std::shared_ptr<const studio::ModelBundle> modelBundle(const QString& name)
{
    return bundleFromFile(QStringLiteral(PADROB_SOURCE_DIR "/models/") + name);
}

QString millScenePath()
{
    return QStringLiteral(PADROB_SOURCE_DIR "/resources/scenes/sag_mill.pad");
}

int channelDiff(QRgb a, QRgb b)
{
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)), std::abs(qBlue(a) - qBlue(b))});
}

struct Stats {
    int distinct = 0;      ///< distinct colours
    double content = 0;    ///< fraction of pixels unlike their row's most common colour
};

/// The background is a vertical gradient: each row's most common colour is background.
Stats stats(const QImage& image)
{
    const QImage im = image.convertToFormat(QImage::Format_RGB32);
    QSet<QRgb> colours;
    long content = 0;
    for (int y = 0; y < im.height(); ++y) {
        QHash<QRgb, int> count;
        const auto* row = reinterpret_cast<const QRgb*>(im.constScanLine(y));
        for (int x = 0; x < im.width(); ++x) {
            ++count[row[x] & 0xffffff];
            colours.insert(row[x] & 0xffffff);
        }
        QRgb mode = 0;
        int best = -1;
        for (auto it = count.cbegin(); it != count.cend(); ++it) {
            if (it.value() > best) {
                best = it.value();
                mode = it.key();
            }
        }
        for (int x = 0; x < im.width(); ++x) content += channelDiff(row[x], mode) > 12 ? 1 : 0;
    }
    return {static_cast<int>(colours.size()), static_cast<double>(content) / (im.width() * im.height())};
}

/// Fraction of pixels that differ by more than a little between two images.
double difference(const QImage& a, const QImage& b)
{
    if (a.size() != b.size()) return 1;
    const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
    long n = 0;
    for (int r = 0; r < x.height(); ++r) {
        const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(r));
        const auto* q = reinterpret_cast<const QRgb*>(y.constScanLine(r));
        for (int c = 0; c < x.width(); ++c) n += channelDiff(p[c], q[c]) > 24 ? 1 : 0;
    }
    return static_cast<double>(n) / (x.width() * x.height());
}

/// Pixels for which `test(r, g, b)` holds.
int countPixels(const QImage& image, const std::function<bool(int, int, int)>& test)
{
    const QImage im = image.convertToFormat(QImage::Format_RGB32);
    int n = 0;
    for (int y = 0; y < im.height(); ++y) {
        const auto* row = reinterpret_cast<const QRgb*>(im.constScanLine(y));
        for (int x = 0; x < im.width(); ++x) n += test(qRed(row[x]), qGreen(row[x]), qBlue(row[x])) ? 1 : 0;
    }
    return n;
}

bool purple(int r, int g, int b) { return b > g + 40 && r > g + 15; }
bool green(int r, int g, int b) { return g > r + 40 && g > b + 30; }
bool yellow(int r, int g, int b) { return r > 170 && g > 140 && b < 80 && r - g < 60; }
bool magenta(int r, int g, int b) { return r > 140 && b > 120 && g < 90; }
bool cyan(int r, int g, int b) { return g > 120 && b > 120 && r < 70; }
// the mill scene's colours, lit: the lamps (drawn glowing), the workers' orange vests
// and yellow hard hats, the yellow bolt pads of the empty liner position
bool lampWhite(int r, int g, int b) { return r > 235 && g > 220 && b > 170 && b < 215; }
bool vestOrange(int r, int g, int b) { return r > 110 && g > 0.3 * r && g < 0.62 * r && b < 0.2 * r; }
bool hatYellow(int r, int g, int b) { return r > 90 && g > 0.8 * r && b < 0.35 * r; }

QImage render(Viewport& view)
{
    return view.grabFramebuffer();
}

/// The liner manipulator in the SAG mill, in `view` shown at 1280 × 720.
bool showLinerInMill(Viewport& view)
{
    auto bundle = modelBundle(QStringLiteral("liner_manipulator.pad"));
    const studio::SceneFile mill = studio::loadSceneFile(millScenePath());
    if (!bundle || !mill.bundle) return false;
    view.resize(1280, 720);
    view.show();
    if (!QTest::qWaitForWindowExposed(&view)) return false;
    view.setBundle(bundle);
    view.setScene(mill.bundle);
    return true;
}

/// A shown viewport of 800 × 600.
struct Shown {
    Viewport view;
    Shown()
    {
        view.resize(800, 600);
        view.show();
    }
    bool exposed() { return QTest::qWaitForWindowExposed(&view); }
};

const char* const kCubeStl = R"(solid cube
facet normal 0 0 -1
 outer loop
  vertex 0 0 0
  vertex 1 1 0
  vertex 1 0 0
 endloop
endfacet
facet normal 0 0 -1
 outer loop
  vertex 0 0 0
  vertex 0 1 0
  vertex 1 1 0
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex 0 0 1
  vertex 1 0 1
  vertex 1 1 1
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex 0 0 1
  vertex 1 1 1
  vertex 0 1 1
 endloop
endfacet
facet normal 0 -1 0
 outer loop
  vertex 0 0 0
  vertex 1 0 0
  vertex 1 0 1
 endloop
endfacet
facet normal 0 -1 0
 outer loop
  vertex 0 0 0
  vertex 1 0 1
  vertex 0 0 1
 endloop
endfacet
facet normal 0 1 0
 outer loop
  vertex 0 1 0
  vertex 1 1 1
  vertex 1 1 0
 endloop
endfacet
facet normal 0 1 0
 outer loop
  vertex 0 1 0
  vertex 0 1 1
  vertex 1 1 1
 endloop
endfacet
facet normal -1 0 0
 outer loop
  vertex 0 0 0
  vertex 0 1 1
  vertex 0 1 0
 endloop
endfacet
facet normal -1 0 0
 outer loop
  vertex 0 0 0
  vertex 0 0 1
  vertex 0 1 1
 endloop
endfacet
facet normal 1 0 0
 outer loop
  vertex 1 0 0
  vertex 1 1 0
  vertex 1 1 1
 endloop
endfacet
facet normal 1 0 0
 outer loop
  vertex 1 0 0
  vertex 1 1 1
  vertex 1 0 1
 endloop
endfacet
endsolid cube
)";

/// A pendulum whose bob is drawn by `graphic` (a G statement on body 1).
QString meshModel(const QString& graphic)
{
    return QStringLiteral("B 1 1.0 0.01 0.01 0.01\n"
                          "C 1 QI 0.3\n"
                          "B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 -1\n"
                          "B2 1 P2 0 0 1 A2 1 0 0 R2 0 0 -1\n"
                          "G 1 B 0 BOX 0.2 0.1 0.1 COLOR 0.4 0.4 0.4\n") +
           graphic + QStringLiteral("\n");
}

bool writeFile(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

std::vector<Eigen::Isometry3d> posesAt(const solver::Model& model, const Eigen::VectorXd& q)
{
    solver::Data data(model);
    solver::forwardKinematics(model, q, Eigen::VectorXd::Zero(model.nb), data);
    return data.X_wb;
}

}  // namespace

class ViewTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { QSurfaceFormat::setDefaultFormat(Viewport::surfaceFormat()); }

private slots:
    void initTestCase() { QVERIFY(QDir().mkpath(screenshotDir())); }

    // ---- geometry without GL ---------------------------------------------------------

    void triangulatesConcavePolygons()
    {
        // an L shape, both windings: the triangles' areas add up to the polygon's (3)
        std::vector<Eigen::Vector2d> l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
        for (int pass = 0; pass < 2; ++pass) {
            const std::vector<int> t = studio::triangulatePolygon(l);
            QCOMPARE(t.size(), std::size_t(12));
            double area = 0;
            for (std::size_t k = 0; k < t.size(); k += 3) {
                const Eigen::Vector2d a = l[t[k]], b = l[t[k + 1]], c = l[t[k + 2]];
                const double signedArea = 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
                QVERIFY(signedArea > 0);  // counter-clockwise
                area += signedArea;
            }
            QVERIFY(std::abs(area - 3) < 1e-12);
            std::reverse(l.begin(), l.end());
        }
        QVERIFY(studio::triangulatePolygon({{0, 0}, {1, 1}, {2, 2}}).empty());
    }

    void shapesArePlacedLikeTheInertiaCalculator()
    {
        // CONE: base at POS, apex at POS + L·AXIS; CYL centred at POS along AXIS
        solver::Diagnostics diags("shapes");
        auto bundle = studio::makeBundle(QStringLiteral("B 1 1 1 1 1\nC 1\nB1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0\n"
                                                        "B2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0\n"
                                                        "G 1 B 1 CONE 0.5 2 POS 1 0 0 AXIS 1 0 0\n"
                                                        "G 2 B 0 CYL 0.1 4 POS 0 0 -3 AXIS 0 1 0\n"),
                                         QString(), diags);
        QVERIFY(bundle);
        auto g = studio::buildSceneGeometry(bundle.get(), studio::initialPoses(*bundle->model));
        QVERIFY(g->problems.isEmpty());
        auto rangeBounds = [&](const studio::DrawRange& r) {
            Eigen::AlignedBox3d box;
            for (std::uint32_t k = r.first; k < r.first + r.count; ++k) {
                const studio::MeshVertex& v = g->mesh.vertices[g->mesh.indices[k]];
                box.extend(Eigen::Vector3d(v.position[0], v.position[1], v.position[2]));
            }
            return box;
        };
        const Eigen::AlignedBox3d cone = rangeBounds(g->dressed[1]);
        QVERIFY((cone.min() - Eigen::Vector3d(1, -0.5, -0.5)).norm() < 1e-5);
        QVERIFY((cone.max() - Eigen::Vector3d(3, 0.5, 0.5)).norm() < 1e-5);
        const Eigen::AlignedBox3d cyl = rangeBounds(g->dressed[0]);
        QVERIFY((cyl.min() - Eigen::Vector3d(-0.1, -2, -3.1)).norm() < 1e-5);
        QVERIFY((cyl.max() - Eigen::Vector3d(0.1, 2, -2.9)).norm() < 1e-5);
        // the grid lies at the scene's lowest point
        QVERIFY(std::abs(g->gridZ + 3.1) < 1e-5);
    }

    void schematicOfTheLinerManipulator()
    {
        auto bundle = modelBundle(QStringLiteral("liner_manipulator.pad"));
        QVERIFY(bundle);
        auto g = studio::sceneGeometry(bundle);
        QCOMPARE(studio::sceneGeometry(bundle).get(), g.get());  // built once, shared
        QCOMPARE(g->nb, bundle->model->nb);
        QVERIFY(g->problems.isEmpty());
        for (int b = 0; b < g->nb; ++b) {
            QVERIFY2(!g->bars[static_cast<std::size_t>(b + 1)].empty(), qPrintable(QString::number(b)));
            QVERIFY(!g->dressed[static_cast<std::size_t>(b + 1)].empty());
            QVERIFY(!g->jointPieces[static_cast<std::size_t>(b)].empty());
        }
        int t1 = 0;
        for (solver::JointType t : bundle->model->jointType) t1 += t == solver::JointType::Actuator ? 1 : 0;
        QCOMPARE(static_cast<int>(g->actuators.size()), t1 + 0);
        QVERIFY(t1 >= 2);
        // the seat looks along +y from behind the base and above it
        QVERIFY(g->seatEye.y() < 0);
        QVERIFY(g->seatEye.z() > 0);
    }

    void cameraZoomKeepsThePointUnderTheCursor()
    {
        studio::Camera c;
        c.target = Eigen::Vector3d(1, 2, 3);
        c.distance = 10;
        const double w = 800, h = 600, x = 620, y = 150;
        auto project = [&](const Eigen::Vector3d& p) {
            const Eigen::Vector4d clip =
                c.projectionMatrix(w / h, c.target, 1, 10) * c.viewMatrix() * p.homogeneous();
            return Eigen::Vector2d((clip.x() / clip.w() + 1) * 0.5 * w, (1 - clip.y() / clip.w()) * 0.5 * h);
        };
        const double hh = c.distance * std::tan(0.5 * c.fieldOfViewY);
        const Eigen::Vector3d under =
            c.target + c.right() * ((2 * x / w - 1) * hh * w / h) + c.up() * ((1 - 2 * y / h) * hh);
        QVERIFY((project(under) - Eigen::Vector2d(x, y)).norm() < 1e-6);
        c.zoom(0.5, x, y, w, h);
        QVERIFY(std::abs(c.distance - 5) < 1e-12);
        QVERIFY((project(under) - Eigen::Vector2d(x, y)).norm() < 1e-6);
        // the seat: heading 0 looks along +y, positive headings turn right (towards +x)
        c.mode = studio::Camera::Mode::Seat;
        c.seatPitch = 0;
        QVERIFY((c.forward() - Eigen::Vector3d::UnitY()).norm() < 1e-12);
        c.yawOffset = std::numbers::pi / 2;
        QVERIFY((c.forward() - Eigen::Vector3d::UnitX()).norm() < 1e-12);
        QVERIFY(std::abs(studio::ViewportLayout::yawOffset(0, 3) + std::numbers::pi / 3) < 1e-12);
        QVERIFY(std::abs(studio::ViewportLayout::yawOffset(1, 2) - std::numbers::pi / 6) < 1e-12);
    }

    // ---- every model, every display mode -----------------------------------------------

    void everyModelInEveryMode_data()
    {
        QTest::addColumn<QString>("file");
        const QStringList files =
            QDir(QStringLiteral(PADROB_SOURCE_DIR "/models")).entryList({QStringLiteral("*.pad")});
        QVERIFY(!files.isEmpty());
        for (const QString& f : files) QTest::newRow(qPrintable(f)) << f;
    }

    void everyModelInEveryMode()
    {
        QFETCH(QString, file);
        auto bundle = modelBundle(file);
        QVERIFY2(bundle, qPrintable(file));
        Shown shown;
        QSignalSpy problems(&shown.view, &Viewport::problem);
        shown.view.setBundle(bundle);
        QVERIFY(shown.exposed());
        shown.view.fitAll();
        const QString base = QFileInfo(file).completeBaseName();
        QImage image[3];
        const DisplayMode modes[3] = {DisplayMode::Schematic, DisplayMode::Dressed, DisplayMode::Both};
        const char* names[3] = {"schematic", "dressed", "both"};
        struct Restore {
            ~Restore() { Viewport::setLighting(Viewport::Lighting::Automatic); }
        } restore;
        for (int k = 0; k < 3; ++k) {
            shown.view.setDisplayMode(modes[k]);
            // lit at every pixel, then at the vertices: the same picture, with fewer
            // shades (a flat face takes one colour)
            Viewport::setLighting(Viewport::Lighting::PerPixel);
            const QImage pixel = render(shown.view);
            save(pixel, base + QLatin1Char('_') + QLatin1String(names[k]) + QStringLiteral("_lit_pixel"));
            Viewport::setLighting(Viewport::Lighting::PerVertex);
            image[k] = render(shown.view);
            save(image[k], base + QLatin1Char('_') + QLatin1String(names[k]));
            const QString what = file + QLatin1Char(' ') + QLatin1String(names[k]);
            const QImage& vertex = image[k];
            for (const auto& [lit, minimum] : {std::pair{&pixel, 100}, std::pair{&vertex, 40}}) {
                const Stats s = stats(*lit);
                QVERIFY2(s.distinct > minimum, qPrintable(QStringLiteral("%1: %2 colours").arg(what).arg(s.distinct)));
                QVERIFY2(s.content > 0.02, qPrintable(QStringLiteral("%1: %2 drawn").arg(what).arg(s.content)));
            }
            QVERIFY2(difference(pixel, image[k]) < 0.01, qPrintable(what));
        }
        QVERIFY2(countPixels(image[0], purple) > 150, qPrintable(file));  // the bodies' bars
        QVERIFY2(countPixels(image[0], green) > 50, qPrintable(file));    // the joints (and the y axis)
        // schematic and dressed: a good part of what is drawn differs (the grid is common)
        const double sd = difference(image[0], image[1]);
        const double drawn = std::max(stats(image[0]).content, stats(image[1]).content);
        QVERIFY2(sd > 0.005 && sd > 0.2 * drawn,
                 qPrintable(QStringLiteral("schematic vs dressed %1 of %2").arg(sd).arg(drawn)));
        QVERIFY2(difference(image[2], image[0]) > 0.002, qPrintable(file));
        QVERIFY2(difference(image[2], image[1]) > 0.002, qPrintable(file));
        QCOMPARE(problems.count(), 0);
        QVERIFY(shown.view.frameMillis() > 0);
        qInfo("%s: median frame %.1f ms, %d vertices", qPrintable(file), shown.view.frameMillis(),
              static_cast<int>(studio::sceneGeometry(bundle)->mesh.vertices.size()));
    }

    // ---- meshes --------------------------------------------------------------------------

    void missingMeshIsReportedOnceAndDrawnAsABox()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString mesh = dir.filePath(QStringLiteral("missing.stl"));
        const QString model = dir.filePath(QStringLiteral("model.pad"));
        // loading checks that the file exists: it goes away after the model is loaded
        QVERIFY(writeFile(mesh, kCubeStl));
        const QString text = meshModel(QStringLiteral("G 2 B 1 MESH \"missing.stl\" SCALE 0.2 COLOR 0.2 0.8 0.8"));
        QVERIFY(writeFile(model, text.toUtf8()));
        auto bundle = bundleFromFile(model);
        QVERIFY(bundle);
        QVERIFY(QFile::remove(mesh));
        Shown shown;
        QSignalSpy problems(&shown.view, &Viewport::problem);
        shown.view.setBundle(bundle);
        QCOMPARE(problems.count(), 1);
        const QString message = problems.at(0).at(0).toString();
        QVERIFY2(message.contains(QStringLiteral("missing.stl")) && message.contains(QStringLiteral("not found")),
                 qPrintable(message));
        QVERIFY(shown.exposed());
        shown.view.fitAll();
        const QImage image = render(shown.view);
        save(image, QStringLiteral("mesh_missing"));
        QVERIFY(stats(image).content > 0.02);
        QVERIFY(countPixels(image, magenta) > 100);  // the placeholder
        shown.view.setBundle(bundle);  // the same bundle again: not reported again
        render(shown.view);
        QCOMPARE(problems.count(), 1);
    }

    void unreadableMeshIsReported()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QVERIFY(writeFile(dir.filePath(QStringLiteral("broken.stl")), "this is not a mesh\n"));
        const QString model = dir.filePath(QStringLiteral("model.pad"));
        QVERIFY(writeFile(model, meshModel(QStringLiteral("G 2 B 1 MESH \"broken.stl\"")).toUtf8()));
        auto bundle = bundleFromFile(model);
        QVERIFY(bundle);
        Shown shown;
        QSignalSpy problems(&shown.view, &Viewport::problem);
        shown.view.setBundle(bundle);
        QCOMPARE(problems.count(), 1);
        QVERIFY(problems.at(0).at(0).toString().contains(QStringLiteral("broken.stl")));
        QVERIFY(shown.exposed());
        QVERIFY(stats(render(shown.view)).content > 0.01);
    }

    void realMeshIsDrawn()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QVERIFY(writeFile(dir.filePath(QStringLiteral("cube.stl")), kCubeStl));
        const QString model = dir.filePath(QStringLiteral("model.pad"));
        // a 0.3 m cyan cube centred on the bob (the mesh's origin is its corner)
        QVERIFY(writeFile(model, meshModel(QStringLiteral("G 2 B 1 MESH \"cube.stl\" SCALE 0.3 POS -0.15 -0.15 -0.15 "
                                                          "COLOR 0.1 0.85 0.85"))
                                     .toUtf8()));
        auto bundle = bundleFromFile(model);
        QVERIFY(bundle);
        Shown shown;
        QSignalSpy problems(&shown.view, &Viewport::problem);
        shown.view.setBundle(bundle);
        QCOMPARE(problems.count(), 0);
        QVERIFY(shown.exposed());
        shown.view.setCamera(QStringLiteral("Side"));
        const QImage image = render(shown.view);
        save(image, QStringLiteral("mesh_cube"));
        QVERIFY2(countPixels(image, cyan) > 2000, qPrintable(QString::number(countPixels(image, cyan))));
        // its faces are lit differently (normals per face)
        shown.view.setCamera(QStringLiteral("Iso"));
        const QImage iso = render(shown.view);
        save(iso, QStringLiteral("mesh_cube_iso"));
        QSet<QRgb> shades;
        const QImage rgb = iso.convertToFormat(QImage::Format_RGB32);
        for (int y = 0; y < rgb.height(); ++y) {
            for (int x = 0; x < rgb.width(); ++x) {
                const QRgb p = rgb.pixel(x, y);
                const int r = qRed(p), g = qGreen(p), b = qBlue(p);
                if (g > 50 && r < g / 2 && std::abs(g - b) < 30) shades.insert(p & 0xf0f0f0);  // cyan, lit or not
            }
        }
        QVERIFY(shades.size() >= 3);
    }

    // ---- poses, cameras, highlight --------------------------------------------------------

    void posesMoveTheModel()
    {
        auto bundle = modelBundle(QStringLiteral("liner_manipulator.pad"));
        QVERIFY(bundle);
        Shown shown;
        shown.view.setBundle(bundle);
        shown.view.setDisplayMode(DisplayMode::Dressed);
        QVERIFY(shown.exposed());
        const QImage before = render(shown.view);
        const solver::Model& model = *bundle->model;
        Eigen::VectorXd q = solver::makeState(model).q;
        q[0] += 0.9;  // slew
        shown.view.setPoses(posesAt(model, q));
        const QImage after = render(shown.view);
        save(after, QStringLiteral("liner_slewed"));
        QVERIFY2(difference(before, after) > 0.02, qPrintable(QString::number(difference(before, after))));
        // poses of the wrong size are ignored
        shown.view.setPoses({});
        QCOMPARE(difference(render(shown.view), after), 0.0);
        // a snapshot carries the same poses
        auto snapshot = std::make_shared<studio::Snapshot>();
        snapshot->bundle = bundle;
        snapshot->bodyPoses = posesAt(model, solver::makeState(model).q);
        shown.view.setSnapshot(snapshot);
        QVERIFY(difference(render(shown.view), before) < 0.001);
    }

    void animationIsCheap()
    {
        // a moving model: only the body matrices change from frame to frame
        auto bundle = modelBundle(QStringLiteral("liner_manipulator.pad"));
        QVERIFY(bundle);
        Shown shown;
        Viewport& v = shown.view;
        v.setBundle(bundle);
        v.setDisplayMode(DisplayMode::Both);
        QVERIFY(shown.exposed());
        const solver::Model& model = *bundle->model;
        const Eigen::VectorXd q0 = solver::makeState(model).q;
        QSignalSpy timed(&v, &Viewport::frameTimed);
        const int frames = 40;
        for (int k = 0; k < frames; ++k) {
            Eigen::VectorXd q = q0;
            q[0] += 0.02 * k;
            v.setPoses(posesAt(model, q));  // schedules a frame
            QVERIFY(QTest::qWaitFor([&] { return timed.count() > k; }, 2000));
        }
        QVERIFY(timed.count() >= frames);
        qInfo("liner manipulator, 800 x 600, both modes, moving: median frame %.1f ms", v.frameMillis());
        QVERIFY(v.frameMillis() < 250);
    }

    void namedCamerasDiffer()
    {
        auto bundle = modelBundle(QStringLiteral("liner_manipulator.pad"));
        QVERIFY(bundle);
        Shown shown;
        shown.view.setBundle(bundle);
        QVERIFY(shown.exposed());
        const QStringList names = Viewport::cameraNames();
        QCOMPARE(names, QStringList({"Iso", "Front", "Side", "Top", "Operator seat"}));
        QVector<QImage> images;
        for (const QString& name : names) {
            QVERIFY(shown.view.setCamera(name));
            QCOMPARE(shown.view.camera(), name);
            images << render(shown.view);
            QVERIFY2(stats(images.back()).content > 0.02, qPrintable(name));
            save(images.back(),
                 QStringLiteral("camera_") + QString(name).replace(QLatin1Char(' '), QLatin1Char('_')).toLower());
            QVERIFY(!Viewport::cameraLabel(name).isEmpty());
        }
        for (int i = 0; i < images.size(); ++i) {
            for (int j = i + 1; j < images.size(); ++j) {
                QVERIFY2(difference(images[i], images[j]) > 0.03,
                         qPrintable(names[i] + QStringLiteral(" ~ ") + names[j]));
            }
        }
        QVERIFY(!shown.view.setCamera(QStringLiteral("Nowhere")));
        // the seat camera turns with the yaw offset
        QVERIFY(shown.view.setCamera(QStringLiteral("Operator seat")));
        shown.view.setYawOffset(0.5);
        QVERIFY(difference(render(shown.view), images.back()) > 0.03);
        shown.view.setYawOffset(0);
        // a seat given by the caller
        shown.view.setOperatorSeat(Eigen::Vector3d(4, 1, 0.5), -std::numbers::pi / 2, 0);
        const QImage fromSide = render(shown.view);
        save(fromSide, QStringLiteral("camera_seat_custom"));
        QVERIFY(difference(fromSide, images.back()) > 0.03);
        QVERIFY(stats(fromSide).content > 0.02);
    }

    void mouseOrbitsPansAndZooms()
    {
        auto bundle = modelBundle(QStringLiteral("liner_manipulator.pad"));
        QVERIFY(bundle);
        Shown shown;
        shown.view.setBundle(bundle);
        QVERIFY(shown.exposed());
        Viewport& v = shown.view;
        const QImage start = render(v);
        auto drag = [&](Qt::MouseButton button, Qt::KeyboardModifiers mods, QPoint from, QPoint to) {
            QMouseEvent press(QEvent::MouseButtonPress, from, v.mapToGlobal(from), button, button, mods);
            QCoreApplication::sendEvent(&v, &press);
            for (int k = 1; k <= 4; ++k) {
                const QPoint p = from + (to - from) * k / 4;
                QMouseEvent move(QEvent::MouseMove, p, v.mapToGlobal(p), Qt::NoButton, button, mods);
                QCoreApplication::sendEvent(&v, &move);
            }
            QMouseEvent release(QEvent::MouseButtonRelease, to, v.mapToGlobal(to), button, Qt::NoButton, mods);
            QCoreApplication::sendEvent(&v, &release);
        };
        const double yaw = v.cameraState().yaw;
        drag(Qt::LeftButton, Qt::NoModifier, {400, 300}, {500, 320});
        QCOMPARE(v.camera(), QString());
        QVERIFY(v.cameraState().yaw != yaw);
        const QImage orbited = render(v);
        QVERIFY(difference(start, orbited) > 0.02);
        const Eigen::Vector3d target = v.cameraState().target;
        drag(Qt::MiddleButton, Qt::NoModifier, {400, 300}, {450, 300});
        QVERIFY((v.cameraState().target - target).norm() > 1e-3);
        const Eigen::Vector3d target2 = v.cameraState().target;
        drag(Qt::LeftButton, Qt::ShiftModifier, {400, 300}, {400, 350});
        QVERIFY((v.cameraState().target - target2).norm() > 1e-3);
        const double distance = v.cameraState().distance;
        QWheelEvent wheel(QPointF(400, 300), v.mapToGlobal(QPointF(400, 300)), QPoint(), QPoint(0, 240), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(&v, &wheel);
        QVERIFY(v.cameraState().distance < 0.8 * distance);
        // the seat camera becomes an orbit camera when dragged
        v.setCamera(QStringLiteral("Operator seat"));
        const Eigen::Vector3d eye = v.cameraState().eye();
        drag(Qt::LeftButton, Qt::NoModifier, {400, 300}, {401, 300});
        QCOMPARE(v.cameraState().mode, studio::Camera::Mode::Orbit);
        QVERIFY((v.cameraState().eye() - eye).norm() < 0.1);
        // fit all frames the model again
        v.fitAll();
        QVERIFY(stats(render(v)).content > 0.02);
    }

    void highlightAndFrames()
    {
        auto bundle = modelBundle(QStringLiteral("liner_manipulator.pad"));
        QVERIFY(bundle);
        Shown shown;
        Viewport& v = shown.view;
        v.setBundle(bundle);
        v.setDisplayMode(DisplayMode::Schematic);
        QVERIFY(shown.exposed());
        v.setCamera(QStringLiteral("Side"));
        const QImage plain = render(v);
        const int before = countPixels(plain, yellow);
        v.setHighlight(1, -1);  // the boom
        const QImage body = render(v);
        save(body, QStringLiteral("highlight_body"));
        QVERIFY2(countPixels(body, yellow) > before + 300, qPrintable(QString::number(countPixels(body, yellow))));
        v.setHighlight(-1, 1);  // the boom's lift cylinder (T 1)
        const QImage joint = render(v);
        save(joint, QStringLiteral("highlight_joint"));
        QVERIFY(countPixels(joint, yellow) > before + 100);
        QCOMPARE(v.highlightedJoint(), 1);
        v.setHighlight(99, 99);  // out of range: none
        QCOMPARE(v.highlightedBody(), -1);
        QCOMPARE(v.highlightedJoint(), -1);
        QCOMPARE(difference(render(v), plain), 0.0);
        // a joint highlighted in the dressed mode shows through the dressing
        v.setDisplayMode(DisplayMode::Dressed);
        const QImage dressed = render(v);
        v.setHighlight(-1, 3);
        QVERIFY(difference(render(v), dressed) > 0.0005);
        v.setHighlight(-1, -1);
        v.setShowFrames(true);
        const QImage frames = render(v);
        save(frames, QStringLiteral("frames"));
        QVERIFY(difference(frames, dressed) > 0.002);
        v.setShowFrames(false);
        v.setShowGrid(false);
        QVERIFY(difference(render(v), dressed) > 0.002);
    }

    // CONTACT: View ▸ Contacts draws a red disc at each contact point and its force as
    // an orange arrow; a box resting on a slab shows its four corners pushed up
    void contactsAreDrawnOnDemand()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("resting_box.pad"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("GRAVITY 0 0 -9.81\nCONTACT MU 0.5\nB 1 100 4.2 4.2 4.2 NAME \"box\"\nC 1 T 3\n"
                "B1 0 P1 0 0 0.25 A1 1 0 0 R1 0 1 0\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0\n"
                "G 1 B 1 BOX 0.5 0.5 0.5 COLOR 0.3 0.5 0.8\nG 2 B 0 BOX 3 3 0.2 POS 0 0 -0.1 COLOR 0.55 0.55 0.55\n");
        f.close();
        auto bundle = bundleFromFile(path);
        QVERIFY(bundle && bundle->model && bundle->model->contact);
        solver::SimulationOptions o;
        o.integrator.step = 1e-3;
        solver::Simulation sim(bundle->model, o);
        std::vector<solver::SimulationEvent> events;
        std::string error;
        QVERIFY2(sim.advanceTo(0.3, events, error), error.c_str());
        const auto snapshot = studio::captureSnapshot(sim, bundle);
        QVERIFY(snapshot->contacts.size() >= 4);
        // the slab carries the box: the contacts' forces on the box add up to its weight
        Eigen::Vector3d total = Eigen::Vector3d::Zero();
        for (const studio::ContactSnapshot& c : snapshot->contacts) total += c.force;
        QVERIFY2(std::abs(total.z() - 100 * 9.81) < 5.0, qPrintable(QString::number(total.z())));
        QVERIFY(snapshot->largestContactForce > 100 * 9.81 / 8);

        Shown shown;
        Viewport& v = shown.view;
        v.setBundle(bundle);
        v.setSnapshot(snapshot);
        QVERIFY(shown.exposed());
        v.setCamera(QStringLiteral("Iso"));
        v.fitAll();
        auto red = [](int r, int g, int b) { return r > 170 && g < 90 && b < 80; };
        auto orange = [](int r, int g, int b) { return r > 200 && g > 90 && g < 190 && b < 60; };
        const QImage off = render(v);
        QVERIFY(!v.showContacts());
        v.setShowContacts(true);
        const QImage on = render(v);
        save(on, QStringLiteral("contacts"));
        QVERIFY2(countPixels(on, red) > countPixels(off, red) + 100, qPrintable(QString::number(countPixels(on, red))));
        QVERIFY2(countPixels(on, orange) > countPixels(off, orange) + 100,
                 qPrintable(QString::number(countPixels(on, orange))));
        v.setShowContacts(false);
        QCOMPARE(difference(render(v), off), 0.0);
    }

    void emptySceneAndFrameTiming()
    {
        Shown shown;
        Viewport& v = shown.view;
        QSignalSpy timed(&v, &Viewport::frameTimed);
        QVERIFY(shown.exposed());
        v.setBundle(nullptr);
        v.setPoses({});
        v.setHighlight(0, 0);
        v.setShowFrames(true);
        const QImage empty = render(v);
        save(empty, QStringLiteral("empty"));
        QVERIFY(stats(empty).content > 0.005);  // the grid and the axes
        v.setBundle(modelBundle(QStringLiteral("pendulum.pad")));
        for (int k = 0; k < 5; ++k) {
            v.update();
            QTest::qWait(30);
        }
        QVERIFY(timed.count() > 0);
        // the context is OpenGL 3.3 core (or newer)
        QVERIFY(v.context());
        const QSurfaceFormat format = v.context()->format();
        QVERIFY(format.version() >= qMakePair(3, 3));
        QCOMPARE(format.profile(), QSurfaceFormat::CoreProfile);
        QVERIFY(timed.last().at(0).toDouble() > 0);
        QVERIFY(v.frameMillis() > 0);
        v.setBundle(nullptr);  // back to nothing
        QVERIFY(stats(render(v)).content > 0.005);
    }

    // ---- a scene around the model ---------------------------------------------------------

    void sceneFilesAndTheMillsDressing()
    {
        const studio::SceneFile mill = studio::loadSceneFile(millScenePath());
        QVERIFY2(mill.bundle, qPrintable(mill.error));
        QVERIFY(mill.note.isEmpty());
        QCOMPARE(mill.bundle->model->nb, 0);
        auto d = studio::sceneDressing(mill.bundle);
        QVERIFY(d);
        QCOMPARE(studio::sceneDressing(mill.bundle).get(), d.get());  // built once, shared
        QVERIFY(!studio::sceneDressing(nullptr));
        QVERIFY(d->problems.isEmpty());
        QCOMPARE(d->skippedGraphics, 0);
        QVERIFY(!d->solids.empty());
        QVERIFY(!d->lamps.empty());
        QVERIFY(!d->lights.empty());  // the work lights
        // at true size: the 36 ft shell (inner radius 5.4864 m, 75 mm plate) around its
        // axis along y through x = 1.3 m, z = 0.30 m
        // (the ends, the floor and the beam may move as the scene is refined: only the
        // shell's section is checked)
        const Eigen::Vector3d hi = d->bounds.max(), lo = d->bounds.min();
        QVERIFY(std::abs(hi.x() - (1.3 + 5.5614)) < 0.01 && std::abs(lo.x() - (1.3 - 5.5614)) < 0.01);
        QVERIFY(std::abs(hi.z() - (0.30 + 5.5614)) < 0.01 && std::abs(lo.z() - (0.30 - 5.5614)) < 0.01);
        QVERIFY(hi.y() - lo.y() > 5.1);  // 16 ft 9 in long at least

        // files that cannot be used say why
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const studio::SceneFile missing = studio::loadSceneFile(dir.filePath(QStringLiteral("nowhere.pad")));
        QVERIFY(!missing.bundle);
        QVERIFY2(missing.error.contains(QStringLiteral("nowhere.pad")), qPrintable(missing.error));
        const QString broken = dir.filePath(QStringLiteral("broken.pad"));
        QVERIFY(writeFile(broken, "G 1 B 0 BOX 1 1\n"));
        const studio::SceneFile bad = studio::loadSceneFile(broken);
        QVERIFY(!bad.bundle);
        QVERIFY2(bad.error.contains(QStringLiteral("broken.pad:1:")), qPrintable(bad.error));  // file:line:col
        // a model used as a scene: only its ground graphics are drawn
        const QString withBodies = dir.filePath(QStringLiteral("bodies.pad"));
        QVERIFY(writeFile(withBodies, meshModel(QStringLiteral("G 2 B 1 BOX 0.1 0.1 0.1")).toUtf8()));
        const studio::SceneFile partly = studio::loadSceneFile(withBodies);
        QVERIFY2(partly.bundle, qPrintable(partly.error));
        QVERIFY(!partly.note.isEmpty());
        QCOMPARE(studio::sceneDressing(partly.bundle)->skippedGraphics, 1);
        const QString groundless = dir.filePath(QStringLiteral("groundless.pad"));
        QVERIFY(writeFile(groundless, meshModel(QString()).replace("G 1 B 0", "G 1 B 1").toUtf8()));
        const studio::SceneFile nothing = studio::loadSceneFile(groundless);
        QVERIFY(!nothing.bundle);
        QVERIFY2(nothing.error.contains(QStringLiteral("ground")), qPrintable(nothing.error));
    }

    void theMillAroundTheLinerManipulator()
    {
        auto bundle = modelBundle(QStringLiteral("liner_manipulator.pad"));
        QVERIFY(bundle);
        const studio::SceneFile mill = studio::loadSceneFile(millScenePath());
        QVERIFY2(mill.bundle, qPrintable(mill.error));
        Viewport view;
        view.resize(1280, 720);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.setBundle(bundle);
        const QImage plain = render(view);
        const double distance = view.cameraState().distance;
        QSignalSpy problems(&view, &Viewport::problem);
        view.setScene(mill.bundle);
        QCOMPARE(view.scene(), mill.bundle);
        QCOMPARE(problems.count(), 0);

        // the default camera: the model framed (not the mill), looking into the mill
        const QImage iso = render(view);
        save(iso, QStringLiteral("scene_mill_iso"));
        QCOMPARE(view.camera(), QStringLiteral("Iso"));
        QCOMPARE(view.cameraState().distance, distance);
        view.fitAll();
        QCOMPARE(view.cameraState().distance, distance);
        // the operator's seat
        QVERIFY(view.setCamera(QStringLiteral("Operator seat")));
        const QImage seat = render(view);
        save(seat, QStringLiteral("scene_mill_seat"));
        // the other cameras, and every display mode: the scene is always dressed
        for (const QString& name : {QStringLiteral("Front"), QStringLiteral("Side"), QStringLiteral("Top")}) {
            QVERIFY(view.setCamera(name));
            save(render(view), QStringLiteral("scene_mill_") + name.toLower());
        }
        view.setCamera(QStringLiteral("Iso"));
        view.setDisplayMode(DisplayMode::Schematic);
        const QImage schematic = render(view);
        save(schematic, QStringLiteral("scene_mill_schematic"));
        view.setDisplayMode(DisplayMode::Dressed);
        for (const auto& [name, image] : {std::pair{"iso", &iso}, std::pair{"seat", &seat},
                                          std::pair{"schematic", &schematic}}) {
            qInfo("mill, %s: %d lamp, %d vest, %d hat pixels", name, countPixels(*image, lampWhite),
                  countPixels(*image, vestOrange), countPixels(*image, hatYellow));
        }

        // the mill all around the machine, a worker in view (vest and hard hat)
        QVERIFY(difference(plain, iso) > 0.3);
        QVERIFY2(countPixels(iso, vestOrange) > 500, qPrintable(QString::number(countPixels(iso, vestOrange))));
        QVERIFY(stats(seat).distinct > 100);
        QVERIFY(difference(plain, seat) > 0.3);
        QVERIFY(countPixels(schematic, vestOrange) > 500);  // the scene dressed in the schematic mode too
        QVERIFY(countPixels(schematic, purple) > 150);      // and the model's bars

        // never highlighted: a highlighted body tints the model only
        view.setHighlight(1, -1);
        const QImage lit = render(view);
        QVERIFY(countPixels(lit, vestOrange) > 100);
        view.setHighlight(-1, -1);

        // no scene: as before
        view.setScene(nullptr);
        QCOMPARE(difference(render(view), plain), 0.0);
    }

    void closedSolidsAreFoundAndTheirBackFacesCulledUnseen()
    {
        // closedWinding: a box and a cylinder are closed solids, wound counter-clockwise
        // seen from outside; reversed, clockwise; with a triangle missing, open
        {
            studio::MeshBuilder m;
            m.box(Eigen::Vector3d(1, 2, 3));
            QCOMPARE(studio::closedWinding(m, 0, std::uint32_t(m.indices.size()), 1e-6), 1);
            studio::MeshBuilder flipped = m;
            for (std::size_t k = 0; k < flipped.indices.size(); k += 3) std::swap(flipped.indices[k], flipped.indices[k + 1]);
            QCOMPARE(studio::closedWinding(flipped, 0, std::uint32_t(flipped.indices.size()), 1e-6), -1);
            QCOMPARE(studio::closedWinding(m, 0, std::uint32_t(m.indices.size()) - 3, 1e-6), 0);
            studio::MeshBuilder c;
            c.cylinder(0.5, 0, 2);
            QCOMPARE(studio::closedWinding(c, 0, std::uint32_t(c.indices.size()), 1e-6), 1);
            studio::MeshBuilder strip;  // two boxes side by side, one turned inside out
            strip.box(Eigen::Vector3d(1, 1, 1));
            strip.append(flipped);
            QCOMPARE(studio::closedWinding(strip, 0, std::uint32_t(strip.indices.size()), 1e-6), 0);
            // a tube: its inner wall faces the axis, its two ends outwards
            studio::MeshBuilder t;
            t.tube(1.0, 0.6, 2.0);
            QCOMPARE(studio::closedWinding(t, 0, std::uint32_t(t.indices.size()), 1e-6), 1);
        }

        // large faces cut into a grid (for lighting at the vertices): still closed solids,
        // no edge longer than asked, neighbouring faces cut alike
        {
            const double edge = 0.3;
            auto longest = [](const studio::MeshBuilder& m) {
                double out = 0;
                for (std::size_t k = 0; k + 2 < m.indices.size(); k += 3) {
                    for (int e = 0; e < 3; ++e) {
                        const float* a = m.vertices[m.indices[k + e]].position;
                        const float* b = m.vertices[m.indices[k + (e + 1) % 3]].position;
                        out = std::max(out, double(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2])));
                    }
                }
                return out;
            };
            studio::MeshBuilder box;
            box.setMaxEdge(edge);
            box.box(Eigen::Vector3d(1, 2, 3));
            // 4 × 7 × 10 cuts: 2 (7·10 + 10·4 + 4·7) quads
            QCOMPARE(box.indices.size(), std::size_t(3 * 2 * 2 * (70 + 40 + 28)));
            QCOMPARE(studio::closedWinding(box, 0, std::uint32_t(box.indices.size()), 1e-6), 1);
            QVERIFY(longest(box) <= edge * std::sqrt(2.0) + 1e-6);  // a cell's diagonal
            // placed turned and moved, the cuts follow the placed lengths
            studio::MeshBuilder placed;
            placed.setMaxEdge(edge);
            Eigen::Affine3d turn = Eigen::Affine3d::Identity();
            turn.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
            turn.translation() = Eigen::Vector3d(5, -2, 1);
            placed.setTransform(turn);
            placed.box(Eigen::Vector3d(1, 2, 3));
            QCOMPARE(placed.indices.size(), box.indices.size());
            QCOMPARE(studio::closedWinding(placed, 0, std::uint32_t(placed.indices.size()), 1e-6), 1);
            for (int shape = 0; shape < 3; ++shape) {
                studio::MeshBuilder m;
                m.setMaxEdge(edge);
                if (shape == 0) m.cylinder(1.0, 0.0, 2.0);
                if (shape == 1) m.tube(1.0, 0.6, 2.0);
                if (shape == 2) m.cone(1.0, 2.0);
                studio::MeshBuilder coarse;
                if (shape == 0) coarse.cylinder(1.0, 0.0, 2.0);
                if (shape == 1) coarse.tube(1.0, 0.6, 2.0);
                if (shape == 2) coarse.cone(1.0, 2.0);
                QCOMPARE(studio::closedWinding(m, 0, std::uint32_t(m.indices.size()), 1e-6), 1);
                QCOMPARE(studio::closedWinding(coarse, 0, std::uint32_t(coarse.indices.size()), 1e-6), 1);
                QVERIFY(m.indices.size() > coarse.indices.size());
                QCOMPARE(m.bounds().min(), coarse.bounds().min());
                QCOMPARE(m.bounds().max(), coarse.bounds().max());
            }
            // without a maximum, as before: one quad a face
            studio::MeshBuilder plain;
            plain.box(Eigen::Vector3d(10, 20, 30));
            QCOMPARE(plain.indices.size(), std::size_t(36));
        }

        // which side of a plane, and whether the near plane's rectangle cuts a solid open:
        // a tube along z (radius 1, bore 0.6, 2 long)
        {
            studio::MeshBuilder t;
            t.tube(1.0, 0.6, 2.0);
            studio::CullPart part;
            part.range = {0, std::uint32_t(t.indices.size())};
            part.box = t.bounds();
            part.winding = studio::closedWinding(t, 0, part.range.count, 1e-6);
            QCOMPARE(studio::planeSide(t, part, Eigen::Vector4d(0, 0, 1, 5)), 1);    // z ≥ −5: all kept
            QCOMPARE(studio::planeSide(t, part, Eigen::Vector4d(0, 0, 1, -5)), -1);  // z ≥ 5: all cut away
            QCOMPARE(studio::planeSide(t, part, Eigen::Vector4d(1, 0, 0, 0)), 0);    // x ≥ 0: cut through
            auto quadAt = [](const Eigen::Vector3d& c, double h) {
                return std::array<Eigen::Vector3d, 4>{c + Eigen::Vector3d(-h, -h, 0), c + Eigen::Vector3d(h, -h, 0),
                                                      c + Eigen::Vector3d(h, h, 0), c + Eigen::Vector3d(-h, h, 0)};
            };
            QVERIFY(studio::solidClearOf(t, part, quadAt(Eigen::Vector3d(0, 0, 0), 0.05), 0.01));   // in the bore
            QVERIFY(studio::solidClearOf(t, part, quadAt(Eigen::Vector3d(3, 0, 0), 0.05), 0.01));   // far outside
            QVERIFY(studio::solidClearOf(t, part, quadAt(Eigen::Vector3d(1.5, 0, 0), 0.05), 0.01)); // beside it
            QVERIFY(!studio::solidClearOf(t, part, quadAt(Eigen::Vector3d(0.8, 0, 0), 0.05), 0.01));  // in the wall
            QVERIFY(!studio::solidClearOf(t, part, quadAt(Eigen::Vector3d(1.0, 0, 0), 0.05), 0.01));  // across it
            // within the margin of the bore
            QVERIFY(!studio::solidClearOf(t, part, quadAt(Eigen::Vector3d(0.57, 0, 0), 0.01), 0.05));
        }

        // the mill and the machine: many closed solids; the pictures are the same with
        // and without culling (the back faces of a closed solid seen from outside never
        // show; solids cut by the section plane or the near plane are not culled)
        auto bundle = modelBundle(QStringLiteral("liner_manipulator.pad"));
        QVERIFY(bundle);
        const studio::SceneFile mill = studio::loadSceneFile(millScenePath());
        QVERIFY2(mill.bundle, qPrintable(mill.error));
        const auto dressing = studio::sceneDressing(mill.bundle);
        const auto geometry = studio::sceneGeometry(bundle);
        int closed = 0, parts = 0;
        for (const auto& p : dressing->solidParts) closed += p.winding != 0 ? 1 : 0;
        parts += int(dressing->solidParts.size());
        for (const auto& slot : geometry->dressedParts) {
            for (const auto& p : slot) closed += p.winding != 0 ? 1 : 0;
            parts += int(slot.size());
        }
        qInfo("mill and liner manipulator: %d of %d graphics are closed solids", closed, parts);
        QVERIFY(closed > parts / 2);

        Viewport view;
        view.resize(1280, 720);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.setBundle(bundle);
        view.setScene(mill.bundle);
        QVERIFY(Viewport::backFaceCulling());  // the default
        struct Restore {
            ~Restore() { Viewport::setLighting(Viewport::Lighting::Automatic); }
        } restore;
        auto compare = [&](const QString& name) {
            for (const auto lighting : {Viewport::Lighting::PerPixel, Viewport::Lighting::PerVertex}) {
                Viewport::setLighting(lighting);
                Viewport::setBackFaceCulling(false);
                const QImage all = render(view);
                Viewport::setBackFaceCulling(true);
                const QImage culled = render(view);
                const double d = difference(all, culled);
                qInfo("%s, lit at %s: %.5f of the pixels differ with culling", qPrintable(name),
                      lighting == Viewport::Lighting::PerPixel ? "every pixel" : "the vertices", d);
                // silhouettes only: where a culled back face met a front face at the same depth
                // (the longest, the feed-end head's opening rim seen from below: a line one
                // pixel wide, 0.11 % of the pixels)
                QVERIFY2(d < 0.0015, qPrintable(name));
                QVERIFY(stats(culled).distinct > 50);
            }
        };
        for (const QString& name : {QStringLiteral("Iso"), QStringLiteral("Operator seat"), QStringLiteral("Front"),
                                    QStringLiteral("Side"), QStringLiteral("Top")}) {
            QVERIFY(view.setCamera(name));
            compare(name);
        }
        // close in, inside the mill among the liners, and the schematic and both modes
        view.setCamera(QStringLiteral("Iso"));
        for (int k = 0; k < 4; ++k) {
            QWheelEvent wheel(QPointF(640, 360), view.mapToGlobal(QPointF(640, 360)), QPoint(), QPoint(0, 360),
                              Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
            QCoreApplication::sendEvent(&view, &wheel);
            compare(QStringLiteral("zoomed in %1").arg(k + 1));
        }
        studio::Camera c = view.cameraState();
        c.yaw += 2.5;
        c.pitch = -0.2;
        view.setCameraState(c);
        compare(QStringLiteral("from below, turned"));
        view.setDisplayMode(DisplayMode::Both);
        compare(QStringLiteral("both"));
        view.setDisplayMode(DisplayMode::Schematic);
        compare(QStringLiteral("schematic"));
    }

    void lightingAtTheVerticesLooksLikeLightingAtEveryPixel()
    {
        // Automatic: at the vertices on a software OpenGL (llvmpipe here), at every pixel
        // on a GPU; the choice is every viewport's at its next frame
        struct Restore {
            ~Restore() { Viewport::setLighting(Viewport::Lighting::Automatic); }
        } restore;
        QCOMPARE(Viewport::lighting(), Viewport::Lighting::Automatic);
        for (const char* name : {"auto", "pixel", "vertex"}) {
            Viewport::Lighting l{};
            QVERIFY(Viewport::lightingFromName(QLatin1String(name), l));
            QCOMPARE(Viewport::lightingName(l), QLatin1String(name));
        }
        Viewport::Lighting unknown = Viewport::Lighting::PerPixel;
        QVERIFY(!Viewport::lightingFromName(QStringLiteral("gouraud"), unknown));
        QCOMPARE(unknown, Viewport::Lighting::PerPixel);

        Viewport view;
        QVERIFY(showLinerInMill(view));
        render(view);
        qInfo("OpenGL renderer: %s", qPrintable(view.renderer()));
        QVERIFY(!view.renderer().isEmpty());
        const bool software = view.renderer().contains(QLatin1String("llvmpipe"), Qt::CaseInsensitive) ||
                              view.renderer().contains(QLatin1String("softpipe"), Qt::CaseInsensitive);
        QCOMPARE(view.lightsPerVertex(), software);

        // mean difference per channel (the pixels that differ by more than 24 of 255:
        // difference())
        auto meanDifference = [](const QImage& a, const QImage& b) {
            const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
            double sum = 0;
            for (int r = 0; r < x.height(); ++r) {
                const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(r));
                const auto* q = reinterpret_cast<const QRgb*>(y.constScanLine(r));
                for (int c = 0; c < x.width(); ++c) {
                    sum += std::abs(qRed(p[c]) - qRed(q[c])) + std::abs(qGreen(p[c]) - qGreen(q[c])) +
                           std::abs(qBlue(p[c]) - qBlue(q[c]));
                }
            }
            return sum / (3.0 * x.width() * x.height());
        };
        for (const QString& camera : {QStringLiteral("Iso"), QStringLiteral("Operator seat")}) {
            QVERIFY(view.setCamera(camera));
            Viewport::setLighting(Viewport::Lighting::PerPixel);
            const QImage pixel = render(view);
            QVERIFY(!view.lightsPerVertex());
            Viewport::setLighting(Viewport::Lighting::PerVertex);
            const QImage vertex = render(view);
            QVERIFY(view.lightsPerVertex());
            const QString tag = camera == QLatin1String("Iso") ? QStringLiteral("iso") : QStringLiteral("seat");
            save(pixel, QStringLiteral("scene_mill_") + tag + QStringLiteral("_lit_pixel"));
            save(vertex, QStringLiteral("scene_mill_") + tag + QStringLiteral("_lit_vertex"));
            const double mean = meanDifference(pixel, vertex), far = difference(pixel, vertex);
            qInfo("%s: lit at the vertices, a pixel differs by %.2f of 255 on average; %.4f of the pixels by more "
                  "than 24",
                  qPrintable(camera), mean, far);
            QVERIFY2(mean < 3.0, qPrintable(camera));
            QVERIFY2(far < 0.02, qPrintable(camera));
            // the workers' vests and hats, and the lamps, stand out alike
            using Test = std::function<bool(int, int, int)>;
            for (const Test& test : {Test(vestOrange), Test(lampWhite)}) {
                const int a = countPixels(pixel, test), b = countPixels(vertex, test);
                QVERIFY2(std::abs(a - b) <= std::max(50, a / 5),
                         qPrintable(QStringLiteral("%1: %2 and %3").arg(camera).arg(a).arg(b)));
            }
        }
    }

    void sceneLampsGlowAndLightTheirSurroundings()
    {
        // a floor and a box 6 m ahead of a pendulum: a lamp (near white), or a grey box
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        auto sceneWith = [&](const QString& name, const char* color) {
            const QString path = dir.filePath(name);
            const QString text = QStringLiteral("G 1 B 0 BOX 30 30 0.2 POS 0 0 -1.1 COLOR 0.5 0.5 0.5\n"
                                                "G 2 B 0 BOX 0.4 0.4 0.3 POS 0 6 -0.3 COLOR %1\n")
                                     .arg(QLatin1String(color));
            return writeFile(path, text.toUtf8()) ? studio::loadSceneFile(path).bundle : nullptr;
        };
        const auto lit = sceneWith(QStringLiteral("lamp.pad"), "1 0.95 0.75");
        const auto grey = sceneWith(QStringLiteral("box.pad"), "0.5 0.5 0.5");
        QVERIFY(lit && grey);
        QCOMPARE(studio::sceneDressing(lit)->lights.size(), std::size_t(1));
        QVERIFY(studio::sceneDressing(grey)->lights.empty());
        Shown shown;
        Viewport& v = shown.view;
        v.setBundle(modelBundle(QStringLiteral("pendulum.pad")));
        QVERIFY(shown.exposed());
        // from 3 m before the box, looking at it (the pendulum behind: nothing cut away)
        v.setOperatorSeat(Eigen::Vector3d(0, 3, 0.3), 0, -0.25);
        v.setCamera(QStringLiteral("Operator seat"));
        // the floor's brightness under the box (the middle column) and 2 m to its side
        auto floorLight = [](const QImage& image, int x) {
            const QImage im = image.convertToFormat(QImage::Format_RGB32);
            double sum = 0;
            for (int y = im.height() * 3 / 4; y < im.height(); ++y) sum += qGray(im.pixel(x, y));
            return sum / (im.height() - im.height() * 3 / 4);
        };
        QImage image[2];
        double pool[2];
        for (int k = 0; k < 2; ++k) {
            v.setScene(k == 0 ? lit : grey);
            image[k] = render(v);
            save(image[k], k == 0 ? QStringLiteral("scene_lamp") : QStringLiteral("scene_no_lamp"));
            pool[k] = floorLight(image[k], image[k].width() / 2) - floorLight(image[k], 10);
        }
        const int lampPixels = countPixels(image[0], lampWhite);
        QVERIFY2(lampPixels > 1000, qPrintable(QString::number(lampPixels)));
        QCOMPARE(countPixels(image[1], lampWhite), 0);
        qInfo("floor under the box minus beside it: %.1f with a lamp, %.1f without", pool[0], pool[1]);
        QVERIFY(pool[0] > 15);
        QVERIFY(pool[0] > pool[1] + 10);
    }

    void theMillOnThreeScreens()
    {
        auto bundle = modelBundle(QStringLiteral("liner_manipulator.pad"));
        const studio::SceneFile mill = studio::loadSceneFile(millScenePath());
        QVERIFY(bundle && mill.bundle);
        studio::ViewportLayout layout;
        layout.setBundle(bundle);
        layout.setScene(mill.bundle);
        layout.resize(1920, 400);
        layout.show();
        QVERIFY(QTest::qWaitForWindowExposed(&layout));
        layout.setScreens(3);
        QVERIFY(QTest::qWaitForWindowExposed(&layout));
        QImage images[3];
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(layout.viewport(i)->scene(), mill.bundle);  // new screens get the scene
            images[i] = layout.viewport(i)->grabFramebuffer();
            save(images[i], QStringLiteral("scene_mill_screens3_%1").arg(i));
            QVERIFY(stats(images[i]).distinct > 100);
        }
        // the left screen looks at the shell at 9 o'clock: the liners and the empty
        // position's yellow bolt pads, past the wall behind the machine (cut away)
        const int pads = countPixels(images[0], hatYellow);
        QVERIFY2(pads > 20, qPrintable(QString::number(pads)));
        // the workers, ahead to the left and to the right, out of the arm's way
        const int vests = countPixels(images[0], vestOrange) + countPixels(images[1], vestOrange) +
                          countPixels(images[2], vestOrange);
        QVERIFY2(vests > 200, qPrintable(QString::number(vests)));
        layout.setScene(nullptr);
        QVERIFY(!layout.viewport(2)->scene());
    }

    // ---- the operator's screens -----------------------------------------------------------

    void threeScreens()
    {
        auto bundle = modelBundle(QStringLiteral("liner_manipulator.pad"));
        QVERIFY(bundle);
        studio::ViewportLayout layout;
        QSignalSpy problems(&layout, &studio::ViewportLayout::problem);
        layout.setBundle(bundle);
        layout.resize(1500, 400);
        layout.show();
        QVERIFY(QTest::qWaitForWindowExposed(&layout));
        // one screen at first: an ordinary view
        QCOMPARE(layout.screens(), 1);
        QCOMPARE(layout.viewport(0)->camera(), QStringLiteral("Iso"));
        QVERIFY(layout.setCamera(QStringLiteral("Side")));
        QVERIFY(!layout.setCamera(QStringLiteral("Nowhere")));
        QCOMPARE(layout.viewport(0)->camera(), QStringLiteral("Side"));
        layout.fitAll();
        QVERIFY(stats(layout.viewport(0)->grabFramebuffer()).content > 0.05);
        QVERIFY(layout.frameMillis() > 0);

        layout.setScreens(3);
        QCOMPARE(layout.screens(), 3);
        QVERIFY(QTest::qWaitForWindowExposed(&layout));
        QImage images[3];
        for (int i = 0; i < 3; ++i) {
            Viewport* v = layout.viewport(i);
            QVERIFY(v);
            QCOMPARE(v->camera(), QStringLiteral("Operator seat"));
            QVERIFY(std::abs(v->yawOffset() - (i - 1) * std::numbers::pi / 3) < 1e-12);
            QCOMPARE(v->bundle(), bundle);
            images[i] = v->grabFramebuffer();
            QVERIFY2(stats(images[i]).distinct > 30, qPrintable(QString::number(i)));
            save(images[i], QStringLiteral("screens3_%1").arg(i));
        }
        QVERIFY(stats(images[1]).content > 0.05);  // the machine is ahead
        QVERIFY(difference(images[0], images[1]) > 0.02);
        QVERIFY(difference(images[1], images[2]) > 0.02);
        QVERIFY(difference(images[0], images[2]) > 0.02);
        QCOMPARE(layout.viewport(3), nullptr);
        // the poses go to every screen
        Eigen::VectorXd q = solver::makeState(*bundle->model).q;
        q[0] += 0.6;
        layout.setPoses(posesAt(*bundle->model, q));
        QVERIFY(difference(layout.viewport(1)->grabFramebuffer(), images[1]) > 0.01);
        QCOMPARE(layout.viewport(2)->poses().size(), std::size_t(bundle->model->nb));

        // separate windows, and back
        layout.setSeparateWindows(true);
        QVERIFY(layout.separateWindows());
        for (int i = 0; i < 3; ++i) {
            Viewport* v = layout.viewport(i);
            QVERIFY(v->window() != &layout);
            QVERIFY(QTest::qWaitForWindowExposed(v->window()));
            const QImage image = v->grabFramebuffer();
            QVERIFY2(stats(image).distinct > 30, qPrintable(QString::number(i)));
            save(image, QStringLiteral("screens3_window_%1").arg(i));
        }
        layout.setSeparateWindows(false);
        QVERIFY(QTest::qWaitForWindowExposed(&layout));
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(layout.viewport(i)->window(), &layout);
            QVERIFY(stats(layout.viewport(i)->grabFramebuffer()).distinct > 30);
        }

        // two screens at ±30°
        layout.setScreens(2);
        QCOMPARE(layout.screens(), 2);
        QVERIFY(std::abs(layout.viewport(0)->yawOffset() + std::numbers::pi / 6) < 1e-12);
        QVERIFY(std::abs(layout.viewport(1)->yawOffset() - std::numbers::pi / 6) < 1e-12);
        QCOMPARE(layout.viewport(0)->poses().size(), std::size_t(bundle->model->nb));
        QVERIFY(QTest::qWaitForWindowExposed(&layout));
        const QImage left = layout.viewport(0)->grabFramebuffer();
        save(left, QStringLiteral("screens2_0"));
        QVERIFY(difference(left, layout.viewport(1)->grabFramebuffer()) > 0.02);
        // back to one screen: the camera chosen before
        layout.setScreens(1);
        QCOMPARE(layout.viewport(0)->camera(), QStringLiteral("Side"));
        QCOMPARE(problems.count(), 0);
    }
};

QTEST_MAIN(ViewTest)
#include "view_test.moc"
