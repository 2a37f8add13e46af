#include "ui/pages/CompensationPage.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QRadioButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>

#include "core/iso/Iso230_2.h"
#include "core/iso/PositioningRuns.h"
#include "ui/models/CompensationTableModel.h"
#include "ui/shell/SelectedCampaignLoader.h"
#include "ui/shell/Session.h"
#include "ui/widgets/CompensationPlot.h"
#include "ui/widgets/ControllerPanel.h"
#include "ui/widgets/TableExportPanel.h"

namespace driftlab::ui {
namespace {

const QString kCompensationEventSource = QStringLiteral("compensation");

}  // namespace

CompensationPage::CompensationPage(Session& session, QWidget* parent)
    : QWidget(parent),
      m_session(session),
      m_run(new QComboBox(this)),
      m_layoutChoice(new QButtonGroup(this)),
      m_perTarget(new QRadioButton(tr("one point per target"), this)),
      m_bySpacing(new QRadioButton(tr("spacing"), this)),
      m_byPoints(new QRadioButton(tr("points"), this)),
      m_spacing(new QDoubleSpinBox(this)),
      m_points(new QSpinBox(this)),
      m_bidirectional(new QCheckBox(tr("bidirectional (+ and − columns)"), this)),
      m_message(new QLabel(this)),
      m_view(new QTableView(this)),
      m_model(new CompensationTableModel(this)),
      m_plot(new CompensationPlot(this)),
      m_export(new TableExportPanel(this)),
      m_controller(new ControllerPanel(session, this)) {
    m_run->setToolTip(tr("The run whose positioning readings give the cold geometric error"));
    m_run->setMinimumContentsLength(6);
    m_layoutChoice->addButton(m_perTarget);
    m_layoutChoice->addButton(m_bySpacing);
    m_layoutChoice->addButton(m_byPoints);
    m_perTarget->setChecked(true);
    m_spacing->setRange(0.001, 10000);
    m_spacing->setDecimals(3);
    m_spacing->setValue(10);
    m_spacing->setSuffix(tr(" mm"));
    m_points->setRange(2, 1024);
    m_points->setValue(21);
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_view->setModel(m_model);
    m_view->verticalHeader()->setDefaultSectionSize(20);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);

    auto* settings = new QHBoxLayout;
    settings->addWidget(new QLabel(tr("Run"), this));
    settings->addWidget(m_run);
    settings->addSpacing(12);
    settings->addWidget(m_perTarget);
    settings->addWidget(m_bySpacing);
    settings->addWidget(m_spacing);
    settings->addWidget(m_byPoints);
    settings->addWidget(m_points);
    settings->addSpacing(12);
    settings->addWidget(m_bidirectional);
    settings->addStretch(1);

    // The table on the left at full height; the plot over the controller on
    // the right: all of it readable at 1280×800 with the docks open.
    auto* controller = new QGroupBox(tr("Controller"), this);
    auto* controllerLayout = new QVBoxLayout(controller);
    controllerLayout->setContentsMargins(6, 4, 6, 4);
    controllerLayout->addWidget(m_controller);
    auto* right = new QSplitter(Qt::Vertical, this);
    right->addWidget(m_plot);
    right->addWidget(controller);
    right->setStretchFactor(0, 1);
    right->setStretchFactor(1, 1);
    right->setSizes({250, 330});
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(m_view);
    split->addWidget(right);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    split->setSizes({480, 520});

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(settings);
    layout->addWidget(m_message);
    layout->addWidget(split, 1);
    layout->addWidget(m_export);

    connect(m_run, &QComboBox::currentIndexChanged, this, &CompensationPage::rebuild);
    connect(m_layoutChoice, &QButtonGroup::buttonToggled, this, [this](QAbstractButton*, bool on) {
        if (on) rebuild();
    });
    connect(m_spacing, &QDoubleSpinBox::valueChanged, this, [this] {
        if (m_bySpacing->isChecked()) rebuild();
    });
    connect(m_points, &QSpinBox::valueChanged, this, [this] {
        if (m_byPoints->isChecked()) rebuild();
    });
    connect(m_bidirectional, &QCheckBox::toggled, this, &CompensationPage::rebuild);
    connect(m_controller, &ControllerPanel::activeTableRead, this,
            [this](const push::TableImage& image) {
                m_model->setActive(image);
                m_plot->show(m_model->table(), m_model->change());
            });
    connect(m_export, &TableExportPanel::exported, this,
            [this](const QString& path, const QStringList& warnings) {
                m_message->setText(tr("Written %1%2")
                                       .arg(path, warnings.isEmpty()
                                                      ? QString()
                                                      : QStringLiteral(" (") +
                                                            warnings.join(QStringLiteral("; ")) +
                                                            QLatin1Char(')')));
                emit m_session.event(QStringLiteral("info"), kCompensationEventSource,
                                     tr("table exported to %1").arg(path));
            });
    connect(m_export, &TableExportPanel::exportFailed, this, &CompensationPage::showError);
    m_loader = new SelectedCampaignLoader(m_session, true, this);
    connect(&m_session, &Session::campaignSelected, this, [this] { m_model->clear(); });
    connect(m_loader, &SelectedCampaignLoader::cleared, this, &CompensationPage::clearCampaign);
    connect(m_loader, &SelectedCampaignLoader::loadingStarted, this,
            [this] { m_message->setText(tr("loading the campaign…")); });
    connect(m_loader, &SelectedCampaignLoader::loaded, this, &CompensationPage::onLoaded);
    m_loader->reload();
}

CompensationPage::~CompensationPage() = default;

void CompensationPage::showError(const QString& message) {
    m_message->setText(
        QStringLiteral("<b style='color:#b00000'>%1</b>").arg(message.toHtmlEscaped()));
    emit m_session.event(QStringLiteral("error"), kCompensationEventSource, message);
}

void CompensationPage::clearCampaign() {
    m_campaign.reset();
    m_run->clear();
    m_model->clear();
    m_plot->clear();
    m_export->setTable(std::nullopt, {});
    m_controller->setTable(std::nullopt, {});
    m_controller->setHistory({});
    m_message->setText(tr("Select a campaign with a positioning run in the campaign tree."));
}

void CompensationPage::onLoaded(const LoadedCampaign& loaded) {
    if (!loaded.campaign) return showError(tr("Loading the campaign: %1").arg(loaded.error));
    m_campaign = loaded.campaign;
    m_controller->setHistory(loaded.pushes);
    fillPositioningRunBox(m_run, *m_campaign);
    rebuild();
}

void CompensationPage::rebuild() {
    std::optional<compensation::CompensationTable> table;
    const QString runId = m_run->currentText();
    const auto finish = [&] {
        m_export->setTable(table, m_campaign ? m_campaign->machine.axis : QString());
        m_controller->setTable(table, runId);
        emit tableUpdated();
    };
    if (!m_campaign) return finish();
    if (runId.isEmpty()) {
        m_model->clear();
        m_plot->clear();
        showError(tr("No run of campaign %1 has positioning readings: a compensation table "
                     "needs an ISO 230-2 positioning run")
                      .arg(m_campaign->name));
        return finish();
    }
    const Run* run = nullptr;
    for (const Run& r : m_campaign->runs)
        if (r.id == runId) run = &r;
    const iso::Evaluation evaluation = iso::evaluate(iso::readingsOf(*run));
    compensation::TableSettings settings;
    if (m_bySpacing->isChecked()) settings.spacing_mm = m_spacing->value();
    if (m_byPoints->isChecked()) settings.points = m_points->value();
    settings.bidirectional = m_bidirectional->isChecked();
    const QString source = tr("run %1 of %2").arg(runId, m_campaign->name);
    if (!evaluation.ok()) {
        m_model->clear();
        m_plot->clear();
        showError(source + QStringLiteral(": ") + evaluation.error);
        return finish();
    }
    const compensation::TableResult built = compensation::buildTable(evaluation, settings);
    if (!built.ok()) {
        m_model->setTable({});
        m_plot->clear();
        showError(source + QStringLiteral(": ") + built.error);
        return finish();
    }
    table = built.table;
    m_model->setTable(built.table);
    m_plot->show(built.table, m_model->change());
    const QStringList warnings = evaluation.warnings + built.warnings;
    m_message->setText(
        tr("%1 points from %2 to %3 mm every %4 mm, max |correction| %5 µm, mean reversal "
           "B̄ %6 µm (%7; ISO 230-2 mean deviations over %8 cycles, correction = −deviation)%9")
            .arg(built.table.size())
            .arg(built.table.position_mm.front(), 0, 'f', 3)
            .arg(built.table.position_mm.back(), 0, 'f', 3)
            .arg(built.table.spacing_mm(), 0, 'f', 3)
            .arg(built.table.maxAbsCorrectionUm(), 0, 'f', 3)
            .arg(built.table.mean_reversal_um, 0, 'f', 3)
            .arg(source)
            .arg(evaluation.cycles)
            .arg(warnings.isEmpty()
                     ? QString()
                     : QStringLiteral("\n⚠ ") + warnings.join(QStringLiteral("\n⚠ "))));
    finish();
}

}  // namespace driftlab::ui
