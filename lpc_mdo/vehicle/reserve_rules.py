"""Named reserve rules of ``mission.reserve.rule``: a time at the reserve condition, its source."""

from dataclasses import dataclass

__all__ = ["RESERVE_PRESETS", "RESERVE_RULES", "ReservePreset"]


@dataclass(frozen=True)
class ReservePreset:
    """A named reserve rule: a time at the reserve condition, and its source."""

    duration: float  # s
    source: str


#: Named reserve rules (``mission.reserve.rule``), each a time flown at the reserve condition.
#: The FAA's rules name the "normal cruising speed", which the default reserve condition (the
#: mission's cruise) is. Not here: IFR rules (14 CFR 91.167: an alternate leg, a distance, and
#: then minutes: not one time at one condition), the powered-lift SFAR No. 120
#: (14 CFR part 194, 2024: VFR 20 min only where the vehicle can land vertically along the whole
#: route, else the airplane minima; its text could not be checked here), and EASA's final reserve
#: for VTOL-capable aircraft (secondary sources only: at least 5 min at go-around speed).
RESERVE_PRESETS = {
    "faa_vfr_day": ReservePreset(
        30 * 60.0,
        "14 CFR 91.151(a)(1): VFR by day, airplanes: fuel to the first point of intended landing "
        "and, at normal cruising speed, for at least 30 minutes",
    ),
    "faa_vfr_night": ReservePreset(
        45 * 60.0,
        "14 CFR 91.151(a)(2): VFR at night, airplanes: to the first point of intended landing "
        "and at normal cruising speed for at least 45 minutes",
    ),
    "faa_vfr_rotorcraft": ReservePreset(
        20 * 60.0,
        "14 CFR 91.151(b): VFR, rotorcraft: to the first point of intended landing and at normal "
        "cruising speed for at least 20 minutes (by day or night)",
    ),
    "nasa_uam": ReservePreset(
        20 * 60.0,
        "NASA's UAM sizing mission (Johnson and Silva, 'NASA concept vehicles and the "
        "engineering of advanced air mobility aircraft', Aeronautical Journal 126, 2022, Fig. 4; "
        "Silva et al., AIAA 2018-3847): a 20-minute cruise reserve after two 37.5 nm legs",
    ),
}


#: Every rule a vehicle file may name: a time, a distance, or a preset.
RESERVE_RULES = ("time", "distance", *RESERVE_PRESETS)
