#include "ui/pages/Iso230_2Page.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFontDatabase>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonDocument>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSaveFile>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>
#include <cmath>

#include "core/iso/AcceptanceJson.h"
#include "core/iso/PositioningRuns.h"
#include "ui/models/AcceptanceModel.h"
#include "ui/models/Iso230_2TargetModel.h"
#include "ui/shell/SelectedCampaignLoader.h"
#include "ui/shell/Session.h"
#include "ui/widgets/Iso230_2Plot.h"
#include "ui/widgets/MachineHistoryView.h"

namespace driftlab::ui {
namespace {

const QString kIsoEventSource = QStringLiteral("iso230-2");

struct Figure {
    const char* key;    ///< as in `iso230-2 --json`
    const char* label;  ///< symbol and meaning
    double iso::AxisResult::*value;
};

const Figure kFigures[] = {
    {"A", "A  bidirectional accuracy", &iso::AxisResult::a_um},
    {"A_up", "A↑ unidirectional accuracy ↑", &iso::AxisResult::a_up_um},
    {"A_down", "A↓ unidirectional accuracy ↓", &iso::AxisResult::a_down_um},
    {"E", "E  bidirectional systematic error", &iso::AxisResult::e_um},
    {"E_up", "E↑ systematic error ↑", &iso::AxisResult::e_up_um},
    {"E_down", "E↓ systematic error ↓", &iso::AxisResult::e_down_um},
    {"M", "M  mean bidirectional positioning error", &iso::AxisResult::m_um},
    {"R", "R  bidirectional repeatability", &iso::AxisResult::r_um},
    {"R_up", "R↑ repeatability ↑", &iso::AxisResult::r_up_um},
    {"R_down", "R↓ repeatability ↓", &iso::AxisResult::r_down_um},
    {"B", "B  reversal error (max |B_i|)", &iso::AxisResult::reversal_um},
    {"B_mean", "B̄  mean reversal error", &iso::AxisResult::mean_reversal_um},
};

}  // namespace

Iso230_2Page::Iso230_2Page(Session& session, QWidget* parent)
    : QWidget(parent),
      m_session(session),
      m_run(new QComboBox(this)),
      m_edition(new QComboBox(this)),
      m_coverage(new QDoubleSpinBox(this)),
      m_message(new QLabel(this)),
      m_warnings(new QLabel(this)),
      m_view(new QTableView(this)),
      m_model(new Iso230_2TargetModel(this)),
      m_plot(new Iso230_2Plot(this)),
      m_history(new MachineHistoryView(this)),
      m_figures(new QGridLayout),
      m_acceptanceModel(new AcceptanceModel(this)),
      m_specSource(new QLabel(this)),
      m_acceptanceText(new QPlainTextEdit(this)) {
    m_run->setMinimumContentsLength(6);
    m_edition->addItem(tr("ISO 230-2:2014"), QStringLiteral("2014"));
    m_edition->addItem(tr("ISO 230-2:2006"), QStringLiteral("2006"));
    m_edition->addItem(tr("ISO 230-2:1997"), QStringLiteral("1997"));
    m_coverage->setRange(0.5, 5);
    m_coverage->setDecimals(2);
    m_coverage->setValue(2);
    m_coverage->setToolTip(tr("Coverage factor k: R↑_i = 2k·s↑_i, A from x̄ ± k·s"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_warnings->setWordWrap(true);
    m_warnings->setStyleSheet(QStringLiteral("color: #a05000"));
    m_view->setModel(m_model);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(20);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);

    auto* settings = new QHBoxLayout;
    settings->addWidget(new QLabel(tr("Run"), this));
    settings->addWidget(m_run);
    settings->addSpacing(12);
    settings->addWidget(new QLabel(tr("Edition"), this));
    settings->addWidget(m_edition);
    settings->addSpacing(12);
    settings->addWidget(new QLabel(tr("k"), this));
    settings->addWidget(m_coverage);
    settings->addStretch(1);

    auto* figures = new QGroupBox(tr("Axis (µm)"), this);
    figures->setLayout(m_figures);
    m_figures->setVerticalSpacing(2);
    int row = 0;
    for (const Figure& f : kFigures) {
        auto* value = new QLabel(figures);
        value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        m_figures->addWidget(new QLabel(QString::fromUtf8(f.label), figures), row, 0);
        m_figures->addWidget(value, row++, 1);
        m_figureLabels.emplace_back(QString::fromLatin1(f.key), value);
    }
    m_figures->setRowStretch(row, 1);

    auto* lower = new QSplitter(Qt::Horizontal, this);
    lower->addWidget(m_plot);
    lower->addWidget(figures);
    lower->setStretchFactor(0, 3);
    lower->setStretchFactor(1, 1);
    lower->setSizes({700, 300});
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_view);
    split->addWidget(lower);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(settings);
    layout->addWidget(m_message);
    layout->addWidget(m_warnings);
    // The run's evaluation, and the same axis over every campaign of the store.
    auto* tabs = new QTabWidget(this);
    tabs->addTab(split, tr("Run"));
    tabs->addTab(acceptanceTab(), tr("Acceptance"));
    tabs->addTab(m_history, tr("Machine history"));
    layout->addWidget(tabs, 1);

    connect(m_run, &QComboBox::currentIndexChanged, this, &Iso230_2Page::evaluateRun);
    connect(m_edition, &QComboBox::currentIndexChanged, this, &Iso230_2Page::evaluateRun);
    connect(m_coverage, &QDoubleSpinBox::valueChanged, this, &Iso230_2Page::evaluateRun);
    m_loader = new SelectedCampaignLoader(m_session, false, this);
    connect(m_loader, &SelectedCampaignLoader::cleared, this, [this] {
        m_campaign.reset();
        m_run->clear();
        m_history->clear();
        m_message->setText(tr("Select a campaign with a positioning run in the campaign tree."));
    });
    connect(m_loader, &SelectedCampaignLoader::loadingStarted, this,
            [this] { m_message->setText(tr("loading the campaign…")); });
    connect(m_loader, &SelectedCampaignLoader::loaded, this, &Iso230_2Page::onLoaded);
    m_loader->reload();
}

Iso230_2Page::~Iso230_2Page() = default;

QWidget* Iso230_2Page::acceptanceTab() {
    auto* tab = new QWidget(this);
    auto* open = new QPushButton(tr("Open specification…"), tab);
    auto* save = new QPushButton(tr("Save specification…"), tab);
    connect(open, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Acceptance specification"),
                                                          QString(), tr("Specification (*.json)"));
        if (!path.isEmpty()) loadSpecification(path);
    });
    connect(save, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save the specification"),
                                                          QStringLiteral("acceptance.json"),
                                                          tr("Specification (*.json)"));
        if (!path.isEmpty()) saveSpecification(path);
    });
    m_specSource->setWordWrap(true);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(open);
    buttons->addWidget(save);
    buttons->addWidget(m_specSource, 1);
    auto* view = new QTableView(tab);
    view->setModel(m_acceptanceModel);
    view->verticalHeader()->hide();
    view->verticalHeader()->setDefaultSectionSize(20);
    view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_acceptanceText->setReadOnly(true);
    m_acceptanceText->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_acceptanceText->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    auto* split = new QSplitter(Qt::Horizontal, tab);
    split->addWidget(view);
    split->addWidget(m_acceptanceText);
    split->setSizes({420, 600});
    auto* layout = new QVBoxLayout(tab);
    layout->addLayout(buttons);
    layout->addWidget(split, 1);
    // Queued: the model is reset by the re-evaluation, not inside its own setData.
    connect(m_acceptanceModel, &AcceptanceModel::tolerancesEdited, this,
            &Iso230_2Page::applyEditedTolerances, Qt::QueuedConnection);
    return tab;
}

bool Iso230_2Page::loadSpecification(const QString& path) {
    QString error;
    auto spec = iso::readAcceptanceSpecification(path, &error);
    if (!spec) {
        showError(error);
        return false;
    }
    m_spec = std::move(spec);
    m_specSource->setText(tr("Specification: %1").arg(path));
    evaluateRun();
    return true;
}

bool Iso230_2Page::saveSpecification(const QString& path) {
    const iso::AcceptanceSpecification spec = m_spec.value_or(iso::AcceptanceSpecification{});
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(QJsonDocument(iso::toJson(spec)).toJson()) < 0 || !file.commit()) {
        showError(tr("Saving the specification %1: %2").arg(path, file.errorString()));
        return false;
    }
    m_specSource->setText(tr("Specification: %1 (saved)").arg(path));
    return true;
}

void Iso230_2Page::applyEditedTolerances() {
    if (!m_campaign) return;
    // Typing a tolerance without a specification starts one with the
    // defaults: readings at 20 °C, every uncertainty not given counted as 0
    // (the budget's notes name each).
    if (!m_spec) {
        m_spec.emplace();
        m_specSource->setText(tr("Specification: typed here (not saved)"));
    }
    m_spec->axes[m_campaign->machine.axis].iso230_2_um = m_acceptanceModel->tolerances();
    evaluateRun();
}

QString Iso230_2Page::figureText(const QString& key) const {
    for (const auto& [name, label] : m_figureLabels)
        if (name == key) return label->text();
    return {};
}

void Iso230_2Page::showError(const QString& message) {
    m_message->setText(
        QStringLiteral("<b style='color:#b00000'>%1</b>").arg(message.toHtmlEscaped()));
    emit m_session.event(QStringLiteral("error"), kIsoEventSource, message);
}

void Iso230_2Page::onLoaded(const LoadedCampaign& loaded) {
    if (!loaded.campaign) return showError(tr("Loading the campaign: %1").arg(loaded.error));
    m_campaign = loaded.campaign;
    QString specError;
    m_spec = iso::campaignAcceptance(*m_campaign, &specError);
    m_specSource->setText(m_spec ? tr("Specification: the campaign's own (campaign.json)")
                          : specError.isEmpty()
                              ? tr("No specification: open one, or type a tolerance")
                              : tr("The campaign's specification is not valid: %1").arg(specError));
    fillPositioningRunBox(m_run, *m_campaign);
    m_history->load(m_session.storePath(), m_campaign->machine.name, m_campaign->machine.axis);
    evaluateRun();
}

void Iso230_2Page::evaluateRun() {
    m_evaluation.reset();
    m_acceptance.reset();
    m_acceptanceModel->setAcceptance(std::nullopt);
    m_acceptanceText->clear();
    m_model->setTargets({});
    m_plot->clear();
    m_warnings->clear();
    for (const auto& [name, label] : m_figureLabels) label->clear();
    if (!m_campaign) return;
    const QString runId = m_run->currentText();
    if (runId.isEmpty()) {
        showError(tr("No run of campaign %1 has positioning readings").arg(m_campaign->name));
        return emit evaluated();
    }
    iso::Settings settings;
    settings.edition = *iso::editionFromString(m_edition->currentData().toString());
    settings.coverage_factor = m_coverage->value();
    const Run* run = nullptr;
    for (const Run& r : m_campaign->runs)
        if (r.id == runId) run = &r;
    const QString source = tr("run %1 of %2").arg(runId, m_campaign->name);
    iso::Evaluation evaluation = iso::evaluate(iso::readingsOf(*run), settings);
    if (!evaluation.ok()) {
        showError(source + QStringLiteral(": ") + evaluation.error);
        return emit evaluated();
    }
    std::optional<double> accuracyTolerance_um;
    if (m_spec) {
        const iso::AxisTolerances* own = m_spec->tolerancesOf(m_campaign->machine.axis);
        m_acceptanceModel->setTolerances(own ? own->iso230_2_um : std::map<QString, double>{});
        iso::PositioningAcceptance acceptance =
            iso::evaluateAcceptance(*m_campaign, *run, *m_spec, settings);
        if (!acceptance.ok()) {
            showError(tr("Acceptance of %1: %2").arg(source, acceptance.error));
            return emit evaluated();
        }
        evaluation = acceptance.evaluation;
        if (own && own->iso230_2_um.count(QStringLiteral("A")))
            accuracyTolerance_um = own->iso230_2_um.at(QStringLiteral("A"));
        m_acceptanceText->setPlainText(iso::acceptanceText(acceptance).join(QLatin1Char('\n')));
        m_acceptanceModel->setAcceptance(acceptance);
        m_acceptance = std::move(acceptance);
    } else {
        m_acceptanceModel->setTolerances({});
    }
    for (std::size_t i = 0; i < std::size(kFigures); ++i) {
        const double v = evaluation.axis.*kFigures[i].value;
        m_figureLabels[i].second->setText(std::isfinite(v) ? QString::number(v, 'f', 3)
                                                           : tr("n/a"));
    }
    m_model->setTargets(evaluation.targets);
    m_plot->show(evaluation, accuracyTolerance_um);
    m_message->setText(tr("%1 evaluation of %2: %3 targets, %4 cycles; deviation = actual − "
                          "target (µm), ↑ = + approach, ↓ = − approach%5")
                           .arg(iso::toString(settings.edition), source)
                           .arg(evaluation.targets.size())
                           .arg(evaluation.cycles)
                           .arg(m_acceptance ? tr("; %1; acceptance %2")
                                                   .arg(m_acceptance->normalisation.description,
                                                        iso::toString(m_acceptance->overall()))
                                             : QString()));
    QStringList notes = evaluation.warnings;
    for (const QString& why : evaluation.skipped) notes << tr("not determined: %1").arg(why);
    m_warnings->setText(
        notes.isEmpty() ? QString() : QStringLiteral("⚠ ") + notes.join(QStringLiteral("\n⚠ ")));
    m_evaluation = std::move(evaluation);
    emit evaluated();
}

}  // namespace driftlab::ui
