#include "app/gui/ScreenshotTour.h"

#include <QApplication>
#include <QDir>
#include <QTabWidget>
#include <QTimer>

#include "ui/pages/ModelsPage.h"
#include "ui/shell/MainWindow.h"

namespace driftlab::gui {
namespace {

/// "ISO 230-2" → "iso230-2", "Sensor health" → "sensor-health", "Set-up" → "setup".
QString fileStem(const QString& tabText) {
    QString stem = tabText.toLower();
    stem.remove(QLatin1Char('&'));
    stem.replace(QStringLiteral("iso "), QStringLiteral("iso"));
    stem.replace(QLatin1Char(' '), QLatin1Char('-'));
    return stem == QLatin1String("set-up") ? QStringLiteral("setup") : stem;
}

bool save(ui::MainWindow* window, const QString& path) {
    if (window->grab().save(path)) return true;
    qWarning("driftlab: cannot write %s", qPrintable(path));
    QApplication::exit(1);
    return false;
}

void showPage(ui::MainWindow* window, QString dir, int page);

/// The Models page's predictions too: measured against predicted, with the
/// prediction interval's band, as gui-models-predictions.png.
void showPredictions(ui::MainWindow* window, QString dir, int page) {
    QTabWidget* results = window->modelsPage()->resultTabs();
    const int shown = results->currentIndex();
    for (int i = 0; i < results->count(); ++i)
        if (results->tabText(i).remove(QLatin1Char('&')) == QLatin1String("Predictions"))
            results->setCurrentIndex(i);
    QTimer::singleShot(400, window, [window, dir, page, results, shown] {
        if (!save(window, QDir(dir).filePath(QStringLiteral("gui-models-predictions.png")))) return;
        results->setCurrentIndex(shown);
        showPage(window, dir, page + 1);
    });
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
        if (!save(window, path)) return;
        if (window->pages()->widget(page) == window->modelsPage())
            showPredictions(window, dir, page);
        else
            showPage(window, dir, page + 1);
    });
}

}  // namespace

void startScreenshotTour(ui::MainWindow& window, const QString& dir, int delay_ms) {
    QDir().mkpath(dir);
    QTimer::singleShot(delay_ms, &window, [&window, dir] { showPage(&window, dir, 0); });
}

}  // namespace driftlab::gui
