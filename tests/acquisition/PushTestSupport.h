#pragma once
// What the push tests share: a simulated controller on 127.0.0.1 (a free port
// chosen by the system, so tests run in parallel), tables, and reading the
// controller's active table back over Modbus as any client would.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "acquisition/modbus/ModbusLink.h"
#include "acquisition/push/TablePush.h"
#include "acquisition/sim/SimulatedController.h"

namespace driftlab::test {

/// `points` points every `spacing_mm` from 0, a smooth error of ±`amplitude_um`.
inline compensation::CompensationTable pushTable(int points, double spacing_mm = 35,
                                                 double amplitude_um = 8, double phase = 0) {
    compensation::CompensationTable table;
    for (int i = 0; i < points; ++i) {
        table.position_mm.push_back(i * spacing_mm);
        const double value = amplitude_um * std::sin(0.37 * i + phase);
        table.correction_plus_um.push_back(value);
        table.correction_minus_um.push_back(value);
    }
    return table;
}

inline std::unique_ptr<sim::SimulatedController> startController(
    sim::SimulatedControllerOptions options = {}) {
    auto controller = std::make_unique<sim::SimulatedController>(options);
    QString error;
    EXPECT_TRUE(controller->start(&error)) << qPrintable(error);
    return controller;
}

/// A controller that takes `capacity` points per table.
inline std::unique_ptr<sim::SimulatedController> startControllerOfCapacity(int capacity) {
    sim::SimulatedControllerOptions options;
    options.capacity = capacity;
    return startController(options);
}

inline modbus::ModbusUrl urlOf(const sim::SimulatedController& controller) {
    return {QStringLiteral("127.0.0.1"), controller.port(), 1};
}

/// Push options for tests: a short wait for the controller, no change limit.
inline push::PushOptions testOptions(double ack_timeout_s = 5) {
    push::PushOptions options;
    options.ack_timeout_s = ack_timeout_s;
    return options;
}

/// The active table (block 2) read over Modbus TCP by a client of its own.
inline push::TableImage readActiveOverModbus(const sim::SimulatedController& controller,
                                             int capacity = push::kMaxCapacity) {
    modbus::ModbusLink link(urlOf(controller));
    QString error;
    push::TableImage image;
    std::vector<std::uint16_t> header, plus, minus;
    if (!link.connect(&error) ||
        !link.readRegisters(push::reg::kActiveHeader, push::kHeaderCount, header, &error)) {
        ADD_FAILURE() << qPrintable(error);
        return image;
    }
    std::copy(header.begin(), header.end(), image.header.begin());
    if (image.version() == 0) return image;
    EXPECT_TRUE(link.readRegisters(push::reg::kActiveData, image.points(), image.plus, &error))
        << qPrintable(error);
    if (image.bidirectional()) {
        EXPECT_TRUE(link.readRegisters(push::reg::kActiveData + capacity, image.points(),
                                       image.minus, &error))
            << qPrintable(error);
    }
    return image;
}

/// The registers a table becomes as version `version`.
inline push::TableImage imageOf(const compensation::CompensationTable& table, std::uint16_t version,
                                int capacity = push::kMaxCapacity) {
    const push::EncodeResult encoded = push::encodeTable(table, version, capacity);
    EXPECT_TRUE(encoded.ok()) << qPrintable(encoded.error);
    return encoded.image;
}

}  // namespace driftlab::test
