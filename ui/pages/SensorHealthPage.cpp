#include "ui/pages/SensorHealthPage.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>
#include <utility>

#include "ui/models/SensorFlagModel.h"
#include "ui/shell/BackgroundJob.h"
#include "ui/shell/SelectedCampaignLoader.h"
#include "ui/shell/Session.h"
#include "ui/widgets/SensorFlagTimeline.h"

namespace driftlab::ui {
SensorHealthPage::SensorHealthPage(Session& session, QWidget* parent)
    : QWidget(parent),
      m_session(session),
      m_run(new QComboBox(this)),
      m_redundant(new QLineEdit(this)),
      m_check(new QPushButton(tr("Check run"), this)),
      m_keep(new QPushButton(tr("Keep in fits"), this)),
      m_leaveOut(new QPushButton(tr("Leave out of fits"), this)),
      m_message(new QLabel(this)),
      m_summary(new QLabel(this)),
      m_view(new QTableView(this)),
      m_model(new SensorFlagModel(this)),
      m_timeline(new SensorFlagTimeline(this)),
      m_job(new BackgroundJob(this)) {
    m_run->setMinimumContentsLength(12);
    m_redundant->setObjectName(QStringLiteral("RedundantPairs"));
    m_redundant->setPlaceholderText(tr("A=B, C=D"));
    m_redundant->setToolTip(
        tr("Channels at the same place (two sensors in one housing), as id=id separated by "
           "commas: Check run flags where a pair drifts apart (driftlab-cli health "
           "--redundant)"));
    m_check->setToolTip(
        tr("Run the sensor self-diagnosis over the run's samples and store what "
           "it finds as its flags (driftlab-cli health --store)"));
    m_keep->setToolTip(tr("Use the selected flagged stretches' samples in the fits, as logged"));
    m_leaveOut->setToolTip(
        tr("Leave the selected flagged stretches' samples out of the fits "
           "again (the default for every flag)"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setWordWrap(true);
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(20);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_view->horizontalHeader()->setStretchLastSection(true);

    auto* bar = new QHBoxLayout;
    bar->addWidget(new QLabel(tr("Run"), this));
    bar->addWidget(m_run);
    bar->addWidget(new QLabel(tr("Redundant pairs"), this));
    bar->addWidget(m_redundant);
    bar->addWidget(m_check);
    bar->addSpacing(24);
    bar->addWidget(new QLabel(tr("Selected stretches:"), this));
    bar->addWidget(m_keep);
    bar->addWidget(m_leaveOut);
    bar->addStretch(1);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_timeline);
    split->addWidget(m_view);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_message);
    layout->addWidget(m_summary);
    layout->addWidget(split, 1);

    connect(m_run, &QComboBox::currentIndexChanged, this, &SensorHealthPage::showRun);
    connect(m_check, &QPushButton::clicked, this, &SensorHealthPage::checkRun);
    connect(m_keep, &QPushButton::clicked, this, [this] { keepSelected(true); });
    connect(m_leaveOut, &QPushButton::clicked, this, [this] { keepSelected(false); });
    m_loader = new SelectedCampaignLoader(m_session, false, this);
    connect(m_loader, &SelectedCampaignLoader::cleared, this, [this] {
        m_campaign.reset();
        m_flags = {};
        m_run->clear();
        m_message->setText(tr("Select a campaign in the campaign tree."));
    });
    connect(m_loader, &SelectedCampaignLoader::loadingStarted, this,
            [this] { m_message->setText(tr("loading the campaign…")); });
    connect(m_loader, &SelectedCampaignLoader::loaded, this, &SensorHealthPage::onLoaded);
    m_loader->reload();
    showRun();
}

SensorHealthPage::~SensorHealthPage() = default;

void SensorHealthPage::showError(const QString& message) {
    m_message->setText(
        QStringLiteral("<b style='color:#b00000'>%1</b>").arg(message.toHtmlEscaped()));
    emit m_session.event(QStringLiteral("error"), QStringLiteral("health"), message);
}

void SensorHealthPage::onLoaded(const LoadedCampaign& loaded) {
    if (!loaded.campaign) return showError(tr("Loading the campaign: %1").arg(loaded.error));
    m_campaign = std::make_shared<const Campaign>(*loaded.campaign);
    m_campaignId = m_session.campaignId().value_or(0);
    const QString current = m_run->currentData().toString();
    {
        const QSignalBlocker block(m_run);
        m_run->clear();
        for (const Run& run : m_campaign->runs)
            m_run->addItem(QStringLiteral("%1 (%2)").arg(run.id, toString(run.kind)), run.id);
        const int again = m_run->findData(current);
        if (again >= 0) m_run->setCurrentIndex(again);
    }
    loadFlags();
}

void SensorHealthPage::loadFlags() {
    if (m_job->isRunning()) {
        m_loadAgain = true;
        return;
    }
    if (!m_campaign) return;
    m_message->setText(tr("reading the sensor flags…"));
    auto result = std::make_shared<CampaignFlags>();
    const QString path = m_session.storePath();
    const qint64 id = m_campaignId;
    std::shared_ptr<const Campaign> campaign = m_campaign;
    m_job->start(
        [result, path, id, campaign](JobControl& control) {
            control.progress(-1);
            *result = loadCampaignFlags(path, id, *campaign);
        },
        [this, result] {
            if (std::exchange(m_loadAgain, false)) return loadFlags();
            m_flags = std::move(*result);
            if (!m_flags.error.isEmpty())
                showError(tr("Reading the sensor flags: %1").arg(m_flags.error));
            else
                m_message->setText(
                    tr("Flags of campaign %1 as stored by \"Check run\" or driftlab-cli health "
                       "--store. The fits leave a flagged stretch's samples out unless it is "
                       "kept.")
                        .arg(m_campaign->name));
            showRun();
            emit flagsShown();
        });
}

void SensorHealthPage::showRun() {
    const QString runId = m_run->currentData().toString();
    const Run* run = nullptr;
    if (m_campaign)
        for (const Run& r : m_campaign->runs)
            if (r.id == runId) run = &r;
    const bool shown = run != nullptr;
    const auto flags = m_flags.runs.find(runId);
    m_model->setFlags(flags == m_flags.runs.end() ? std::vector<ShownFlag>() : flags->second);
    if (shown)
        m_timeline->show(*m_campaign, *run, m_model->flags());
    else
        m_timeline->clear();
    m_check->setEnabled(shown);
    m_keep->setEnabled(m_model->rowCount() > 0);
    m_leaveOut->setEnabled(m_model->rowCount() > 0);
    if (!shown) return m_summary->clear();
    std::size_t kept = 0, total = 0;
    for (const ShownFlag& f : m_model->flags()) kept += f.flag.kept;
    for (const auto& [id, samples] : m_flags.left_out) total += samples;
    const auto leftOut = m_flags.left_out.find(runId);
    m_summary->setText(
        tr("<b>Run %1: %2 flagged stretch(es), %3 samples left out of the fits</b>, %4 "
           "stretch(es) kept; campaign: %5 samples left out.")
            .arg(runId)
            .arg(m_model->rowCount())
            .arg(leftOut == m_flags.left_out.end() ? 0 : leftOut->second)
            .arg(kept)
            .arg(total));
}

void SensorHealthPage::checkRun() {
    std::vector<sensors::RedundantPair> pairs;
    for (const QString& text : m_redundant->text().split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const auto pair = sensors::parseRedundantPair(text);
        if (!pair) {
            showError(tr("Redundant pairs: '%1' is not two channels, A=B").arg(text.trimmed()));
            return;
        }
        pairs.push_back(*pair);
    }
    const QString runId = m_run->currentData().toString();
    const QString path = m_session.storePath();
    const qint64 id = m_campaignId;
    change(tr("checking run %1…").arg(runId),
           [path, id, runId, pairs] { return checkRunFlags(path, id, runId, pairs); });
}

void SensorHealthPage::keepSelected(bool kept) {
    std::vector<qint64> ids;
    for (const QModelIndex& row : m_view->selectionModel()->selectedRows())
        ids.push_back(m_model->flags()[std::size_t(row.row())].flag.id);
    if (ids.empty()) {
        m_message->setText(tr("Select the flagged stretches in the table first."));
        return;
    }
    const QString path = m_session.storePath();
    change(kept ? tr("keeping %1 flagged stretch(es) in the fits…").arg(ids.size())
                : tr("leaving %1 flagged stretch(es) out of the fits…").arg(ids.size()),
           [path, ids, kept] { return keepFlags(path, ids, kept); });
}

void SensorHealthPage::change(const QString& doing, std::function<QString()> work) {
    if (m_job->isRunning()) return;
    m_message->setText(doing);
    for (QPushButton* b : {m_check, m_keep, m_leaveOut}) b->setEnabled(false);
    auto error = std::make_shared<QString>();
    m_job->start(
        [error, work](JobControl& control) {
            control.progress(-1);
            *error = work();
        },
        [this, error, doing] {
            if (!error->isEmpty()) {
                showError(*error);
                showRun();
                return emit flagsShown();
            }
            emit m_session.event(QStringLiteral("info"), QStringLiteral("health"),
                                 QString(doing).remove(QStringLiteral("…")) + tr(": done"));
            // The campaign is read again, and with it its flags.
            m_session.notifyStoreChanged();
        });
}

}  // namespace driftlab::ui
