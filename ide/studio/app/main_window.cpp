#include "ide/studio/app/main_window.h"

namespace studio {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {}

MainWindow::~MainWindow() = default;

void MainWindow::openInitial(const QString& path) { (void)path; }

}  // namespace studio
