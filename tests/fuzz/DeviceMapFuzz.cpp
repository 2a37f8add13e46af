// libFuzzer target: the input is a device register map (JSON) through
// parseChannelRegisterMap, the reader under loadChannelRegisterMap. A refusal
// (nullopt with a message) is the expected answer to bad input; nothing may
// throw. An accepted map must keep the promises its readers rely on: every
// channel fits below register 65536, no two share a register, the read plan
// covers each register once in requests of at most 125, and each channel
// decodes a few edge-case words without undefined behaviour.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "acquisition/devices/ChannelRegisterMap.h"
#include "acquisition/devices/TemperatureModule.h"

namespace devices = driftlab::devices;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const QByteArray json(reinterpret_cast<const char*>(data), qsizetype(size));
    QString error;
    const auto map = devices::parseChannelRegisterMap(json, &error);
    if (!map) {
        if (error.isEmpty()) std::abort();  // a refusal must say why
        return 0;
    }
    if (map->channels.empty()) std::abort();

    std::size_t registers = 0;
    for (const devices::ChannelSpec& channel : map->channels) {
        const int count = channel.registerCount();
        if (count != 1 && count != 2) std::abort();
        if (channel.address < 0 || channel.address + count > 65536) std::abort();
        registers += std::size_t(count);
        static const std::uint16_t words[][2] = {{0, 0},           {0x7FFF, 0xFFFF}, {0x8000, 0},
                                                 {0xFFFF, 0xFFFF}, {0x7F80, 0},      {0x41AC, 1}};
        for (const auto& pair : words) {
            const devices::DecodedValue v = devices::decodeChannel(channel, pair);
            if ((v.status == devices::DecodeStatus::Ok) == std::isnan(v.value)) std::abort();
        }
    }
    std::size_t planned = 0;
    for (const devices::ReadBlock& block : devices::planReads(*map)) {
        if (block.count < 1 || block.count > 125 || block.address < 0 ||
            block.address + block.count > 65536)
            std::abort();
        planned += std::size_t(block.count);
    }
    // Channels do not overlap, so the plan reads exactly their registers.
    if (planned != registers) std::abort();
    return 0;
}
