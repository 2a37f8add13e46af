#include "acquisition/devices/TemperatureModule.h"

#include <algorithm>
#include <limits>
#include <numeric>

#include "acquisition/modbus/ModbusLink.h"

namespace driftlab::devices {

std::vector<ReadBlock> planReads(const ChannelRegisterMap& map, int max_registers) {
    std::vector<const ChannelSpec*> sorted;
    for (const ChannelSpec& c : map.channels) sorted.push_back(&c);
    std::sort(sorted.begin(), sorted.end(), [](const ChannelSpec* a, const ChannelSpec* b) {
        return std::pair(int(a->kind), a->address) < std::pair(int(b->kind), b->address);
    });
    std::vector<ReadBlock> blocks;
    for (const ChannelSpec* c : sorted) {
        const int count = c->registerCount();
        if (!blocks.empty()) {
            ReadBlock& last = blocks.back();
            if (last.kind == c->kind && last.address + last.count == c->address &&
                last.count + count <= max_registers) {
                last.count += count;
                continue;
            }
        }
        blocks.push_back({c->kind, c->address, count});
    }
    return blocks;
}

TemperatureModule::TemperatureModule(ChannelRegisterMap map, modbus::ModbusUrl url,
                                     double response_timeout_s)
    : m_map(std::move(map)),
      m_plan(planReads(m_map, modbus::kMaxReadRegisters)),
      m_link(std::make_unique<modbus::ModbusLink>(std::move(url), response_timeout_s)) {}

TemperatureModule::~TemperatureModule() = default;

bool TemperatureModule::connect(QString* error) {
    return m_link->connect(error);
}

void TemperatureModule::close() {
    m_link->close();
}

bool TemperatureModule::isConnected() const {
    return m_link->isConnected();
}

int TemperatureModule::requests() const {
    return m_link->requests();
}

std::optional<TemperatureReading> TemperatureModule::read(QString* error) {
    const std::size_t n = m_map.channels.size();
    TemperatureReading reading;
    reading.values.assign(n, std::numeric_limits<double>::quiet_NaN());
    reading.status.assign(n, ChannelStatus::NotRead);
    reading.raw.assign(n, 0);
    std::vector<std::uint16_t> words;
    for (const ReadBlock& block : m_plan) {
        QString block_error;
        const bool ok =
            block.kind == RegisterKind::Input
                ? m_link->readInputRegisters(block.address, block.count, words, &block_error)
                : m_link->readRegisters(block.address, block.count, words, &block_error);
        if (!ok) {
            // A closed link means the transport failed: no reading at all.
            if (!m_link->isConnected()) {
                *error = block_error;
                return std::nullopt;
            }
            if (!reading.warning.isEmpty()) reading.warning += QStringLiteral("; ");
            reading.warning += block_error;
            continue;
        }
        for (std::size_t i = 0; i < n; ++i) {
            const ChannelSpec& c = m_map.channels[i];
            const int at = c.address - block.address;
            if (c.kind != block.kind || at < 0 || at + c.registerCount() > block.count) continue;
            const DecodedValue v = decodeChannel(
                c, std::span<const std::uint16_t>(words).subspan(at, c.registerCount()));
            reading.values[i] = v.value;
            reading.raw[i] = v.raw;
            reading.status[i] =
                v.status == DecodeStatus::Ok ? ChannelStatus::Ok : ChannelStatus::InvalidRaw;
        }
    }
    // Stamped after the last request: the values are at most this old.
    reading.time_utc = QDateTime::currentDateTimeUtc();
    return reading;
}

std::optional<PolledReading> TemperatureModule::poll(QString* error) {
    std::optional<TemperatureReading> reading = read(error);
    if (!reading) return std::nullopt;
    return PolledReading{reading->time_utc, QVariant::fromValue(*reading)};
}

QString toString(ChannelStatus status) {
    switch (status) {
        case ChannelStatus::Ok:
            return QStringLiteral("ok");
        case ChannelStatus::InvalidRaw:
            return QStringLiteral("invalid raw");
        case ChannelStatus::NotRead:
            return QStringLiteral("not read");
    }
    return {};
}

}  // namespace driftlab::devices
