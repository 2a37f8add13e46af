#include "app/gui/ScreenshotTour.h"

#include <QApplication>
#include <QDir>
#include <QTabWidget>
#include <QTimer>

#include "ui/app/MainWindow.h"

namespace driftlab::gui {
namespace {

/// "ISO 230-2" → "iso230-2", "Set-up" → "setup".
QString fileStem(const QString& tabText) {
    QString stem = tabText.toLower();
    stem.remove(QLatin1Char(' '));
    stem.remove(QLatin1Char('&'));
    return stem == QLatin1String("set-up") ? QStringLiteral("setup") : stem;
}

void showPage(ui::MainWindow* window, QString dir, int page) {
    QTabWidget* tabs = window->pages();
    if (page >= tabs->count()) {
        QApplication::exit(0);
        return;
    }
    tabs->setCurrentIndex(page);
    // One event-loop turn later the page is laid out and painted.
    QTimer::singleShot(400, window, [window, dir, page] {
        const QString path = QDir(dir).filePath(
            QStringLiteral("gui-%1.png").arg(fileStem(window->pages()->tabText(page))));
        if (!window->grab().save(path)) {
            qWarning("driftlab: cannot write %s", qPrintable(path));
            QApplication::exit(1);
            return;
        }
        showPage(window, dir, page + 1);
    });
}

}  // namespace

void startScreenshotTour(ui::MainWindow& window, const QString& dir, int delay_ms) {
    QDir().mkpath(dir);
    QTimer::singleShot(delay_ms, &window, [&window, dir] { showPage(&window, dir, 0); });
}

}  // namespace driftlab::gui
