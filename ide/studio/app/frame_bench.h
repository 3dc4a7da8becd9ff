#pragma once
// padrob-studio --bench-frames N: how fast the application starts and draws, and how
// steady its real-time loop stays while it draws, measured in the real window.
//
// It opens the model (the liner manipulator by default) and the scene in a MainWindow
// of 1920 × 1080 (docks hidden, so the 3D view fills it), with settings of its own
// (application name "padrob-studio-bench": the user's layout, recent files and scene
// are neither used nor changed). Then:
//  1. start-up: from the process's start (/proc/self/stat) and from main() to the end
//     of the first frame that shows the model (and the scene);
//  2. with the simulation running and every drive following a slow sine (commands
//     written to the runner), for one view and for three (the operator's screens):
//     N frames paced by the window's own 60 Hz poll timer (time between frames, time
//     to draw), then N frames back to back (new poses, drawn and swapped to the screens:
//     the pure cost of a frame; also the process's CPU time per frame, all threads,
//     which other programs on a busy machine disturb less than the wall time) — each
//     with the solver's step periods meanwhile;
//  3. the input-to-solver latency of 60 key presses: trainer::KeyboardDevice (the 3D
//     view's keys) → the station's input thread → SimulationRunner → the first
//     snapshot whose command has the new value, while the window keeps drawing at
//     60 Hz (a profile mapping the first key pair, Q / A, to the first drive);
//  4. prints the results (text, or one JSON object: docs/performance.md lists the
//     keys) and returns the exit code.
// Also padrob-studio --screenshot FILE (saveScreenshot): the normal start, the window
// saved as an image once the model is drawn, then quit (the package's test uses it).

#include <QElapsedTimer>
#include <QString>

namespace studio {

struct FrameBenchOptions {
    int frames = 100;         ///< frames per measurement (≥ 1)
    QString modelPath;        ///< "": the bundled liner manipulator
    QString scenePath;        ///< "": no scene
    int views = 0;            ///< 1 or 3: that layout only; 0: one view, then three
    bool json = false;        ///< one JSON object on stdout, else lines of text
    QElapsedTimer sinceMain;  ///< started first thing in main()
};

/// Runs the bench (the QApplication exists, its event loop need not run), prints the
/// results on stdout and returns the exit code: 0, or 1 when the model cannot be
/// opened or drawn or the simulation fails (said on stderr). A scene that cannot be
/// used is reported (JSON "scene_error") and the bench goes on without it.
int runFrameBench(const FrameBenchOptions& options);

class MainWindow;
/// padrob-studio --screenshot FILE: waits (at most 60 s) for the first frame of the 3D
/// view that shows `window`'s model, saves the window as an image to FILE (PNG, JPEG…:
/// by its extension), prints the model's file on stdout and returns 0;
/// 1 when no model was drawn or FILE cannot be written (said on stderr).
int saveScreenshot(MainWindow& window, const QString& file);

}  // namespace studio
