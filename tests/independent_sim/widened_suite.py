"""The widened hidden-effect suite: effects entering where, when and with a sign
the cause library's candidates do not assume, sensor faults on every kind of
sensor, rigs with fewer sensors or runs, and logs with holes, jitter and two
merged sampling rates.  Each entry: name, seed, expected, description,
effects_fn(spec, omega_max) and the rig's changes (`rig`):

  drop        channel kinds the rig lacks ("air", "struct", ...)
  n_runs      runs in the campaign (default 4-5)
  jitter_frac sample-time jitter as a fraction of the interval
  merged      thermometers every 10 s, axis columns every 2 s in one samples.csv
  holes       [(run index, start as fraction of the run, minutes, kinds)]
  overrides   make_spec's overrides (geometry, environment, interferometer)

`expected` is fixed here from physics; `widened.py` (with its base refit)
records the numbers behind each label and checks them (see README.md,
"Widened suite").
"""
MODULE_SCREW = ("nut", "bfix", "bfree")            # one Modbus module: the screw's sensors
MODULE_ROOM = ("amb", "air", "struct", "motor")    # the other: room, air, structure, motor

AIR_ENV = {"air_gain_K_W": 0.2, "air_hvac_amp_K": 1.0, "air_hvac_period_min": 50.0, "air_heat_tau_s": 1200.0}
FR_ENV = {"struct_gain_K_W": 0.22, "struct_heat_tau_s": 1800.0}


def _h1(sp, om, rise, m):
    """h1 so that h rises by rise x h0 at the campaign's top speed."""
    return rise * sp["physics"]["h0_W_m2K"] / om ** m


def suite():
    S = []

    def add(name, seed, expected, desc, effects_fn=None, **rig):
        S.append({"name": name, "seed": seed, "expected": expected, "description": desc,
                  "effects_fn": effects_fn, "rig": rig})

    def lag(kind, tau):
        return lambda sp, om: {"sensor_lag": {"channel": _cid(sp, kind), "tau_s": tau}}

    def offset(kind, k):
        return lambda sp, om: {"sensor_offset": {"channel": _cid(sp, kind), "offset_K": k}}

    # 1. heat entering elsewhere ---------------------------------------------------------
    add("motor_heat_flange_lag", 2101, ["motor_heat"],
        "motor loss k*torque^2 through a 15 min motor lag, spread over the bearing pair and flange "
        "(8-88 mm from the fixed end), not into the end cell; nut sensor holes of 4 and 5 min",
        lambda sp, om: {"motor_heat": {"k_W_per_Nm2": 0.7, "tau_s": 900.0, "region_mm": [8.0, 88.0]}},
        overrides={"fixed_end_mm": -95.0},
        holes=[(0, 0.45, 4.0, ("nut",)), (2, 0.3, 5.0, ("nut",))])
    add("motor_heat_flange_nolag", 2102, ["motor_heat"],
        "motor loss k*torque^2 with no lag at all, spread over 5-95 mm from the fixed end",
        lambda sp, om: {"motor_heat": {"k_W_per_Nm2": 0.55, "tau_s": 0.0, "region_mm": [5.0, 95.0]}},
        overrides={"fixed_end_mm": -100.0})
    add("motor_heat_lag30", 2103, ["motor_heat"],
        "motor loss k*torque^2 into the fixed bearing's region through a 30 min lag",
        lambda sp, om: {"motor_heat": {"k_W_per_Nm2": 1.0, "tau_s": 1800.0}})
    add("combo_motor_heat_frame_growth", 2104, ["frame_growth", "motor_heat"],
        "motor loss over the flange (10-90 mm, 20 min lag) and frame growth (6 um/K, 2 h lag)",
        lambda sp, om: {"motor_heat": {"k_W_per_Nm2": 0.65, "tau_s": 1200.0, "region_mm": [10.0, 90.0]},
                        "frame_growth": {"g_um_K": 6.0, "tau_s": 7200.0}},
        overrides={"fixed_end_mm": -100.0, "env": dict(FR_ENV, struct_gain_K_W=0.33)})
    add("bearing_support_heavy", 2105, ["unexplained"],
        "support (free-end) bearing heat 4x c_b|omega|, fixed bearing 0.4x: a per-end law the base model lacks",
        lambda sp, om: {"bearing_asym": {"fix_factor": 0.4, "free_factor": 4.0}},
        overrides={"two_bearings": False, "c_b": 0.025})

    # 2. lags of minutes to hours --------------------------------------------------------
    add("frame_growth_lag3h5", 2201, ["frame_growth"],
        "axis zero shifts 5 um/K of the structure temperature lagged by 3.5 h",
        lambda sp, om: {"frame_growth": {"g_um_K": 5.0, "tau_s": 12600.0}},
        overrides={"env": dict(FR_ENV, struct_gain_K_W=0.2)})
    add("sensor_lag_nut_12min", 2202, None, "nut sensor follows the screw under the nut with a 12 min lag",
        lag("nut", 720.0))
    add("sensor_lag_bearing_14min", 2203, None, "fixed-bearing sensor lags its seat by 14 min", lag("bfix", 840.0))

    # 3. either sign ---------------------------------------------------------------------
    add("frame_growth_negative", 2301, ["frame_growth"],
        "axis zero moves -3 um/K of the structure temperature lagged 1.2 h; holes in the ambient (8 min) "
        "and air (6 min) channels",
        lambda sp, om: {"frame_growth": {"g_um_K": -3.0, "tau_s": 4320.0}},
        overrides={"env": dict(FR_ENV)},
        holes=[(1, 0.5, 8.0, ("amb",)), (3, 0.35, 6.0, ("air",))])
    add("sensor_offset_nut_negative", 2302, None, "nut sensor reads -0.28 K", offset("nut", -0.28))
    add("air_refraction_overcompensated", 2303, ["air_refraction"],
        "environmental compensation applied twice: the reading drifts +0.95 ppm/K x air rise (s = -1)",
        lambda sp, om: {"air_refraction": {"s": -1.0}},
        overrides={"dead_path_mm": 500.0, "env": dict(AIR_ENV, air_gain_K_W=0.25, air_hvac_amp_K=1.3)})
    add("combo_frame_growth_negative_bearing_lag", 2304, None,
        "frame growth -5.5 um/K (1.5 h lag) and a 10 min lag on the fixed-bearing sensor",
        lambda sp, om: {"frame_growth": {"g_um_K": -5.5, "tau_s": 5400.0},
                        "sensor_lag": {"channel": _cid(sp, "bfix"), "tau_s": 600.0}},
        overrides={"env": dict(FR_ENV, struct_gain_K_W=0.3)})

    # 4. sensor faults on every kind of sensor ---------------------------------------------
    add("sensor_offset_ambient", 2401, None,
        "ambient (room) sensor reads -0.35 K: every run starts with the screw at room temperature",
        offset("amb", -0.35))
    add("combo_air_refraction_air_sensor_lag", 2402, None,
        "compensation off (s = 1), and the air sensor follows the beam air with a 15 min lag",
        lambda sp, om: {"air_refraction": {"s": 1.0}, "sensor_lag": {"channel": _cid(sp, "air"), "tau_s": 900.0}},
        overrides={"dead_path_mm": 500.0, "environment_compensation": False,
                   "env": dict(AIR_ENV, air_gain_K_W=0.15, air_hvac_amp_K=1.4, air_hvac_period_min=60.0)})
    add("sensor_offset_structure", 2403, [],
        "structure sensor reads +0.45 K, no other effect: a constant offset on a sensor read through its rise",
        offset("struct", 0.45))
    add("sensor_offset_support_bearing", 2404, None, "support-bearing sensor reads -0.3 K",
        offset("bfree", -0.3), overrides={"two_bearings": True})
    add("sensor_lag_air_compensated", 2405, [],
        "air sensor lags the beam air by 12 min with the compensation working: the air sensor is read by nothing",
        lag("air", 720.0), overrides={"env": dict(AIR_ENV, air_gain_K_W=0.15, air_hvac_period_min=40.0)})

    # 5. rigs with fewer sensors -----------------------------------------------------------
    add("no_air_forced_convection", 2501, ["forced_convection"], "no air thermometer; h = h0 + h1*|omega|^0.9 (+2.6 h0 at the top speed)",
        lambda sp, om: {"forced_convection": {"m": 0.9, "h1": _h1(sp, om, 2.6, 0.9)}}, drop=("air",))
    add("no_structure_nut_heat_exponent", 2502, ["nut_heat_exponent"],
        "no structure thermometer; Q_nut = c*omega_ref*(|omega|/omega_ref)^1.7",
        lambda sp, om: {"nut_heat_exponent": {"n": 1.7}}, drop=("struct",))
    add("no_structure_frame_growth", 2503, ["unexplained"],
        "no structure thermometer; frame growth 5 um/K of the (unlogged) structure lagged 10 min; "
        "the structure warms with the machine's heat within 15 min",
        lambda sp, om: {"frame_growth": {"g_um_K": 5.0, "tau_s": 600.0}},
        drop=("struct",), overrides={"dead_path_mm": 50.0, "env": dict(
            FR_ENV, struct_gain_K_W=0.16, struct_heat_tau_s=900.0)})
    add("null_few_sensors", 2504, [],
        "base physics; nut, fixed bearing and ambient only; 3 runs; sample-time jitter +/-40 % of the interval",
        drop=("air", "struct", "motor"), n_runs=3, jitter_frac=0.4, overrides={"two_bearings": False})

    # 6. two or three runs -----------------------------------------------------------------
    add("null_two_runs", 2601, [], "base physics, 2 runs; the ambient sensor has a 7 min hole",
        n_runs=2, holes=[(1, 0.4, 7.0, ("amb",))])
    add("forced_convection_three_runs", 2602, ["forced_convection"],
        "3 runs; h = h0 + h1*|omega|^1.0 (+2 h0 at the top speed); the screw module is silent for 6 min",
        lambda sp, om: {"forced_convection": {"m": 1.0, "h1": _h1(sp, om, 2.0, 1.0)}},
        n_runs=3, holes=[(0, 0.5, 6.0, MODULE_SCREW)])
    add("frame_growth_two_runs", 2603, ["frame_growth"], "2 runs; frame growth 3.5 um/K, 1 h lag",
        lambda sp, om: {"frame_growth": {"g_um_K": 3.5, "tau_s": 3600.0}}, n_runs=2, overrides={"env": dict(FR_ENV)})

    # 7. holes and merged sampling -----------------------------------------------------------
    add("null_module_hole", 2701, [],
        "base physics; the room module (ambient, air and structure sensors) silent 9 min in one run, "
        "the screw module 5 min in another",
        holes=[(0, 0.55, 9.0, MODULE_ROOM), (2, 0.25, 5.0, MODULE_SCREW)])
    add("null_merged_rates", 2702, [],
        "base physics; thermometers every 10 s and position/feed/torque every 2 s merged in one samples.csv",
        n_runs=4, merged=True)
    return S


def _cid(spec, kind):
    for c in spec["channels"]:
        if c["kind"] == kind:
            return c["id"]
    raise KeyError(kind)
