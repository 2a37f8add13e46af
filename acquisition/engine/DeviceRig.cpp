#include "acquisition/engine/DeviceRig.h"

#include "acquisition/engine/DeviceRunSource.h"

namespace driftlab::engine {
DeviceRig::DeviceRig(DeviceRigSpec spec) : m_spec(std::move(spec)) {}

QString DeviceRig::describe() const {
    QString text = QStringLiteral("temperature module %1 at %2:%3")
                       .arg(m_spec.temperature_map.name, m_spec.temperature_url.host)
                       .arg(m_spec.temperature_url.port);
    if (m_spec.controller_url)
        text += QStringLiteral(", controller at %1").arg(m_spec.controller_url->endpoint());
    if (m_spec.interferometer)
        text += QStringLiteral(", interferometer at %1:%2")
                    .arg(m_spec.interferometer->host)
                    .arg(m_spec.interferometer->port);
    return text;
}

Campaign DeviceRig::campaignHeader(const std::vector<procedures::PlannedRun>&) const {
    Campaign c;
    if (m_spec.campaign_template) {
        c = *m_spec.campaign_template;
        c.runs.clear();
    } else {
        c.machine.name = QStringLiteral("machine on %1").arg(m_spec.temperature_url.host);
        for (const auto& channel : m_spec.temperature_map.channels)
            c.channels.push_back({channel.id,
                                  Quantity::Temperature,
                                  ChannelRole::Other,
                                  QStringLiteral("temperature module channel"),
                                  std::nullopt,
                                  {}});
    }
    c.sample_columns.clear();
    for (const auto& channel : c.channels) c.sample_columns.push_back(channel.id);
    if (m_spec.controller_url)
        c.sample_columns.insert(c.sample_columns.end(),
                                {kPositionColumn, kFeedColumn, kTorqueColumn});
    return c;
}

std::unique_ptr<RunSource> DeviceRig::open(const procedures::PlannedRun& run, std::size_t,
                                           const std::vector<QString>& columns, QString*) {
    return std::make_unique<DeviceRunSource>(m_spec, columns, run);
}

}  // namespace driftlab::engine
