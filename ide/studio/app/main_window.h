#pragma once
// MainWindow: padrob-studio's window. Three workspaces (DESIGN.md): Model (editor,
// model tree, 3D viewport, plots), Station and Train (their issues). Menus File,
// Edit, View, Simulation, Help; layout and recent files persist in QSettings.

#include <QMainWindow>

namespace studio {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Opens `path`, or the bundled liner manipulator when it is empty.
    void openInitial(const QString& path);
};

}  // namespace studio
