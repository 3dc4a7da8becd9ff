#pragma once
// MainWindow's menus and the actions whose texts retranslate() sets: built once by
// buildMenus() (main_window_menus.cpp), owned by the window. A private header of
// ide/studio/app (main_window.cpp and main_window_menus.cpp).

#include "ide/studio/app/main_window.h"
#include "ide/studio/view/viewport.h"

#include <QString>

#include <utility>
#include <vector>

class QAction;
class QMenu;

namespace studio {

struct MainWindow::MenuItems {
    QMenu *file = nullptr, *examples = nullptr, *edit = nullptr, *view = nullptr, *camera = nullptr, *scene = nullptr,
          *screens = nullptr, *simulation = nullptr, *speed = nullptr, *settings = nullptr, *language = nullptr,
          *lighting = nullptr, *help = nullptr;
    QAction *newModel = nullptr, *open = nullptr, *save = nullptr, *saveAs = nullptr, *quit = nullptr;
    QAction *undo = nullptr, *redo = nullptr, *apply = nullptr, *inertia = nullptr;
    QAction *fitAll = nullptr, *loadScene = nullptr, *noScene = nullptr, *frames = nullptr, *contacts = nullptr, *separate = nullptr;
    QAction* record = nullptr;  ///< View ▸ Record Video… (Stop Recording while recording)
    QAction *keyboard = nullptr, *reference = nullptr, *about = nullptr, *gettingStarted = nullptr;
    std::vector<std::pair<QAction*, DisplayMode>> displayModes;
    std::vector<std::pair<QAction*, QString>> cameras;  ///< with the camera's name (Viewport::cameraNames)
    std::vector<std::pair<QAction*, int>> screenCounts;
    std::vector<std::pair<QAction*, double>> speeds;
    std::vector<std::pair<QAction*, QString>> languages;  ///< with the language's code
    std::vector<std::pair<QAction*, Viewport::Lighting>> lightings;
};

}  // namespace studio
