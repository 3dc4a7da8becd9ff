// The fluid-power liner manipulator in padrob-studio (a real window under Xvfb): the
// Model workspace's hydraulics dock comes with a model that has pumps and goes with
// one that has none; the boom lift lever raises the supply pressure and the pump's
// flow in the panel, whose values are the solver's step for step; the plots offer the
// chamber pressures and the pump's supply pressure and flow; the Train workspace's
// attempt shows the panel beside the 3D view (never over it), folded away by its box.
// Screenshots at 1280×720 and 1920×1080 in English and Spanish:
// fluid_model_<size>_<lang>.png and fluid_train_<size>_<lang>.png.

#include "tests/studio/gui_test.h"
#include "ide/paths/paths.h"
#include "ide/i18n/language.h"
#include "ide/studio/app/main_window.h"
#include "ide/studio/plots/plot_panel.h"
#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/hydraulic_panel.h"
#include "ide/studio/sim/simulation_runner.h"
#include "ide/studio/train/train_page.h"
#include "ide/studio/train/tutorial_runner.h"
#include "ide/studio/view/viewport.h"
#include "solver/integrate/simulation.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QFile>
#include <QLineSeries>
#include <QSettings>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <memory>
#include <tuple>

using namespace studio;
using studio::test::screenshotPath;
using studio::test::settle;

namespace {

const QString kSource = QStringLiteral(PADROB_SOURCE_DIR);

/// Opens a model and waits until it is applied (the editor checks it on a worker thread).
bool openAndWait(MainWindow& w, const QString& name)
{
    const quint64 before = w.bundle() ? w.bundle()->serial : 0;
    if (!w.openFile(kSource + "/models/" + name)) return false;
    return QTest::qWaitFor([&] { return w.bundle() && w.bundle()->serial != before; }, 10000);
}

/// The window at `width` × `height`, settled, saved as `name`.
void shoot(MainWindow& w, int width, int height, const QString& name)
{
    w.resize(width, height);
    settle(600);
    QVERIFY(w.grab().save(screenshotPath(name)));
}

/// T0 (reach a target) on `model` (a file of models/), as `dir`/t0.tut.
bool writeTutorial(const QTemporaryDir& dir, const QString& model)
{
    QFile original(kSource + "/resources/tutorials/t0_reach.tut");
    if (!original.open(QIODevice::ReadOnly)) return false;
    QString text = QString::fromUtf8(original.readAll());
    text.replace(QRegularExpression("^MODEL \"[^\"]*\"", QRegularExpression::MultilineOption),
                 "MODEL \"" + kSource + "/models/" + model + "\"");
    text.replace("../../models", kSource + "/models");
    text.replace("\"t0_reach.demo", "\"" + kSource + "/resources/tutorials/t0_reach.demo");
    QFile copy(dir.filePath("t0.tut"));
    return copy.open(QIODevice::WriteOnly) && copy.write(text.toUtf8()) > 0;
}

}  // namespace

class AppFluidTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("PadrobTest");
        QCoreApplication::setApplicationName("padrob-studio-fluid-test");
        QSettings().clear();  // (the attempts go to this test's own trainee records)
        QVERIFY(i18n::install("en"));
    }

    void theModelWorkspaceShowsTheHydraulics()
    {
        MainWindow w;
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* dock = w.findChild<QDockWidget*>("HydraulicsDock");
        QVERIFY(dock);
        HydraulicPanel* panel = w.hydraulics();

        // a model without pumps: no dock
        QVERIFY(openAndWait(w, "liner_manipulator.pad"));
        QTRY_VERIFY(panel->snapshot() && panel->snapshot()->bundle == w.bundle());
        QVERIFY(!panel->hasFluidPower());
        QVERIFY(!dock->isVisible());
        QVERIFY(!w.plots()->signalKeys().contains("pA:2"));

        // the fluid-power one: the dock, one pump, nine sections labelled by their joints
        QVERIFY(openAndWait(w, "liner_manipulator_fluid.pad"));
        QTRY_VERIFY(panel->snapshot() && panel->snapshot()->bundle == w.bundle());
        QVERIFY(panel->hasFluidPower());
        QTRY_VERIFY(dock->isVisible());
        const solver::Model& m = *w.bundle()->model;
        QCOMPARE(panel->snapshot()->pumps.size(), std::size_t(1));
        QCOMPARE(panel->snapshot()->circuits.size(), std::size_t(9));
        const int lift = m.jointIndex(2);
        int liftCircuit = -1;
        for (std::size_t c = 0; c < m.circuits.size(); ++c)
            if (m.circuits[c].joint == lift) liftCircuit = int(c);
        QVERIFY(liftCircuit >= 0);
        QCOMPARE(panel->sectionLabel(liftCircuit), QStringLiteral("C 2 LEVANTE PLUMA"));
        QVERIFY2(panel->pumpLabel(0).startsWith("Pump 1: "), qPrintable(panel->pumpLabel(0)));
        const PumpSnapshot rest = panel->snapshot()->pumps[0];
        QCOMPARE(rest.pmax, 25e6);
        QVERIFY(!rest.saturated());
        const double restA = panel->snapshot()->circuits[std::size_t(liftCircuit)].pressureA;

        // the plots offer the pressures and the pump
        PlotPanel* plots = w.plots();
        for (const char* key : {"pA:2", "pB:2", "pA:1", "pB:9", "pS:1", "Qp:1"})
            QVERIFY2(plots->signalKeys().contains(key), key);
        QCOMPARE(plots->signalUnit("pA:2"), QStringLiteral("MPa"));
        QCOMPARE(plots->signalUnit("Qp:1"), QStringLiteral("L/min"));
        QCOMPARE(plots->signalLabel("pA:2"), QStringLiteral("C 2 LEVANTE PLUMA p_A [MPa]"));
        QVERIFY(plots->signalLabel("pS:1").startsWith("pump 1 "));
        plots->setSignalSelected("pA:2", true);
        plots->setSignalSelected("pS:1", true);
        plots->setSignalSelected("Qp:1", true);
        QCOMPARE(plots->chartCount(), 2);  // MPa and L/min

        // the boom lift lever, full: the supply rises from the margin, the pump delivers
        w.runner()->setCommand(lift, 1.0);
        w.run();
        QTRY_VERIFY_WITH_TIMEOUT(panel->snapshot()->t >= 0.3, 15000);
        const PumpSnapshot early = panel->snapshot()->pumps[0];
        QTRY_VERIFY_WITH_TIMEOUT(w.runner()->latest() && w.runner()->latest()->t >= 1.0, 15000);
        w.pause();
        QTRY_VERIFY(!w.runner()->isRunning());
        QTRY_VERIFY(panel->snapshot() == w.runner()->latest());
        const auto snap = panel->snapshot();
        const PumpSnapshot& pump = snap->pumps[0];
        const CircuitSnapshot& section = snap->circuits[std::size_t(liftCircuit)];
        QVERIFY2(pump.supplyPressure > rest.supplyPressure + 1e6,
                 qPrintable(QString("%1 → %2 Pa").arg(rest.supplyPressure).arg(pump.supplyPressure)));
        QVERIFY2(early.flow > rest.flow + 1e-4 && pump.flow > rest.flow + 1e-4,
                 qPrintable(QString("%1 → %2 → %3 m^3/s").arg(rest.flow).arg(early.flow).arg(pump.flow)));
        QVERIFY(section.spool > 0.9);
        QVERIFY(section.flowA > 1e-4 && section.flowB < 0);
        QVERIFY(section.pressureA > restA);
        QVERIFY(pump.supplyPressure > section.pressureA);
        // every value is the solver's, step for step (RK4 at 1 ms with the same command)
        solver::SimulationOptions o;
        o.integrator.method = solver::IntegrationMethod::Rk4Fixed;
        o.integrator.step = 1e-3;
        solver::Simulation sim(w.bundle()->model, o);
        sim.setCommand(lift, 1.0);
        std::vector<solver::SimulationEvent> ev;
        std::string err;
        for (long k = 1; k <= snap->step; ++k) QVERIFY(sim.advanceTo(k * 1e-3, ev, err));
        const solver::Data& d = sim.data();
        QCOMPARE(pump.supplyPressure, d.supplyPressure[0]);
        QCOMPARE(pump.flow, d.pumpFlow[0]);
        QCOMPARE(pump.demand, d.pumpDemand[0]);
        QCOMPARE(pump.qmax, m.pumps[0].qmax);
        for (std::size_t c = 0; c < m.circuits.size(); ++c) {
            const CircuitSnapshot& s = snap->circuits[c];
            const auto i = Eigen::Index(c);
            QCOMPARE(s.joint, m.circuits[c].joint);
            QCOMPARE(s.spool, sim.state().fluid[solver::kFluidStates * i]);
            QCOMPARE(s.pressureA, d.pressureA[i]);
            QCOMPARE(s.pressureB, d.pressureB[i]);
            QCOMPARE(s.flowA, d.flowA[i]);
            QCOMPARE(s.flowB, d.flowB[i]);
            QCOMPARE(s.relief, 25e6);
            QCOMPARE(s.cavitation, d.cavitation[c]);
        }
        // readable numbers: MPa and L/min
        const QString pumpText = panel->pumpSummary(0);
        QVERIFY2(pumpText.contains(QString("Supply pressure: %1 of 25.0 MPa")
                                       .arg(QLocale().toString(pump.supplyPressure / 1e6, 'f', 1))),
                 qPrintable(pumpText));
        QVERIFY2(pumpText.contains(" of 66.6 L/min"), qPrintable(pumpText));
        const QString sectionText = panel->sectionSummary(liftCircuit);
        QVERIFY2(sectionText.startsWith("C 2 LEVANTE PLUMA\nSpool: +") && sectionText.contains("Relief setting: 25.0 MPa"),
                 qPrintable(sectionText));
        // the plots: the supply pressure rose over the run
        plots->refresh();
        QLineSeries* supply = plots->series("pS:1");
        QVERIFY(supply && supply->count() > 10);
        QVERIFY(supply->at(supply->count() - 1).y() > supply->at(0).y() + 1.0);
        QVERIFY(plots->series("Qp:1")->at(plots->series("Qp:1")->count() - 1).y() > 5.0);

        // screenshots, both sizes, both languages
        shoot(w, 1280, 720, "fluid_model_1280_en.png");
        QVERIFY(panel->isVisible() && panel->height() > 100);
        shoot(w, 1920, 1080, "fluid_model_1920_en.png");
        i18n::switchTo("es");
        settle(200);
        QVERIFY2(panel->pumpLabel(0).startsWith("Bomba 1: "), qPrintable(panel->pumpLabel(0)));
        QVERIFY2(panel->pumpSummary(0).contains(" de 66,6 L/min"), qPrintable(panel->pumpSummary(0)));
        QCOMPARE(dock->windowTitle(), QStringLiteral("Hidráulica"));
        shoot(w, 1920, 1080, "fluid_model_1920_es.png");
        shoot(w, 1280, 720, "fluid_model_1280_es.png");
        i18n::switchTo("en");
        settle(200);

        // back to a model without pumps: the dock goes
        QVERIFY(openAndWait(w, "liner_manipulator.pad"));
        QTRY_VERIFY(!dock->isVisible());
        QVERIFY(w.close());
    }

    // Relief, saturation and cavitation, as the panel marks them (a made-up snapshot).
    void thePanelMarksReliefSaturationAndCavitation()
    {
        solver::Diagnostics diagnostics("liner_manipulator_fluid.pad");
        const auto bundle = makeBundleFromFile(kSource + "/models/liner_manipulator_fluid.pad", diagnostics);
        QVERIFY(bundle);
        solver::Simulation sim(bundle->model, solver::SimulationOptions{});
        auto snapshot = captureSnapshot(sim, bundle);
        QCOMPARE(snapshot->circuits.size(), std::size_t(9));
        PumpSnapshot& pump = snapshot->pumps[0];
        pump.flow = pump.qmax;
        pump.demand = 1.5 * pump.qmax;
        pump.supplyPressure = 24.8e6;
        CircuitSnapshot& lift = snapshot->circuits[1];
        lift.spool = -0.6;
        lift.pressureA = 24.6e6;  // ≥ 98 % of 25 MPa
        lift.pressureB = 0;
        lift.cavitation = 2;
        HydraulicPanel panel;
        panel.resize(560, 320);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        panel.setSnapshot(snapshot);
        QVERIFY(snapshot->pumps[0].saturated());
        const QString pumpText = panel.pumpSummary(0);
        QVERIFY2(pumpText.contains("Demand of the open sections: 99.9 L/min") && pumpText.contains("Saturated"),
                 qPrintable(pumpText));
        const QString liftText = panel.sectionSummary(1);
        QVERIFY2(liftText.contains("Spool: −60 %") && liftText.contains("Chamber A is at the relief setting.") &&
                     liftText.contains("Chamber B cavitates.") && !liftText.contains("Chamber A cavitates."),
                 qPrintable(liftText));
        settle(100);
        QVERIFY(panel.grab().save(screenshotPath("fluid_panel_marks_en.png")));
        // wide: the sections' rows one under the other, at least a row each
        QVERIFY(panel.findChild<QWidget*>("HydraulicsCanvas")->minimumHeight() >= 11 * panel.fontMetrics().height());
    }

    void theTrainAttemptShowsTheHydraulicsBesideTheView()
    {
        QTemporaryDir plain, fluid;
        QVERIFY(plain.isValid() && fluid.isValid());
        QVERIFY(writeTutorial(plain, "liner_manipulator.pad"));
        QVERIFY(writeTutorial(fluid, "liner_manipulator_fluid.pad"));
        MainWindow w;
        w.openInitial(QString());
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.setWorkspace(MainWindow::Workspace::Train);
        TrainPage* page = w.trainPage();
        TutorialRunner* runner = w.tutorialRunner();
        HydraulicPanel* panel = page->hydraulicPanel();
        QCheckBox* box = page->hydraulicsBox();
        page->setAllUnlocked(true);

        // T0 on the machine without pumps: no panel, no box
        page->setTutorialsDir(plain.path());
        QVERIFY(page->openTutorial("T0"));
        page->startAttempt(page->demoLog());
        QTRY_VERIFY_WITH_TIMEOUT(runner->latest() && runner->latest()->snapshot->t > 0.2, 10000);
        QTRY_VERIFY(panel->snapshot() && panel->snapshot()->bundle);
        QVERIFY(!panel->hasFluidPower());
        QVERIFY(!panel->isVisible() && !box->isVisible());
        page->stopAttempt();
        QTRY_VERIFY(page->screen() == TrainPage::Screen::Result);
        page->showCourse();

        // the same stage on the fluid-power machine, driven by its demonstration
        page->setTutorialsDir(fluid.path());
        QVERIFY(page->openTutorial("T0"));
        QVERIFY(page->demoLog());
        page->startAttempt(page->demoLog());
        QTRY_VERIFY_WITH_TIMEOUT(runner->latest() && runner->latest()->snapshot->t > 1.5, 15000);
        runner->setPaused(true);
        settle(300);
        QVERIFY(panel->hasFluidPower());
        QVERIFY(panel->isVisible() && box->isVisible() && box->isChecked());
        QCOMPARE(panel->sectionLabel(1), QStringLiteral("C 2 LEVANTE PLUMA"));
        QCOMPARE(panel->snapshot()->circuits.size(), std::size_t(9));
        QVERIFY(panel->snapshot()->pumps[0].supplyPressure > 2.5e6);  // above the margin: a lever is open
        for (const auto& [width, height, size] : {std::tuple{1280, 720, "1280"}, std::tuple{1920, 1080, "1920"}}) {
            shoot(w, width, height, QString("fluid_train_%1_en.png").arg(size));
            // beside the view, never over it
            Viewport* view = page->attemptViewport();
            const QRect viewRect(view->mapTo(&w, QPoint(0, 0)), view->size());
            const QRect panelRect(panel->mapTo(&w, QPoint(0, 0)), panel->size());
            QVERIFY2(!viewRect.intersects(panelRect), qPrintable(QString("view %1,%2 %3×%4, panel %5,%6 %7×%8")
                                                                      .arg(viewRect.x()).arg(viewRect.y())
                                                                      .arg(viewRect.width()).arg(viewRect.height())
                                                                      .arg(panelRect.x()).arg(panelRect.y())
                                                                      .arg(panelRect.width()).arg(panelRect.height())));
            QVERIFY(viewRect.width() > panelRect.width() * 2);
        }
        i18n::switchTo("es");
        settle(200);
        QCOMPARE(box->text(), QStringLiteral("Hidráulica"));
        shoot(w, 1920, 1080, "fluid_train_1920_es.png");
        shoot(w, 1280, 720, "fluid_train_1280_es.png");
        i18n::switchTo("en");
        settle(200);
        // the box folds it away, and is remembered
        box->setChecked(false);
        QVERIFY(!panel->isVisible());
        QCOMPARE(QSettings().value("trainer/showHydraulics").toBool(), false);
        box->setChecked(true);
        QVERIFY(panel->isVisible());
        page->stopAttempt();
        QTRY_VERIFY(page->screen() == TrainPage::Screen::Result);
        page->setTutorialsDir(paths::tutorialsDir());
        QVERIFY(w.close());
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::surfaceFormat());
    QApplication app(argc, argv);
    AppFluidTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "app_fluid_test.moc"
