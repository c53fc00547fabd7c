import copy

import pytest

BASE = {
    "meta": {"name": "test conveyor"},
    "screw_conveyor": {
        "throughput": "7.2 t/h",
        "length": "21 m",
        "inclination": "10 deg",
        "material": {
            "bulk_density": "1.2 t/m^3",
            "filling": 0.4,
            "speed_coefficient": 45,
            "resistance": 2.5,
            "cema_material_factor": 1.0,
        },
        "screw": {"pitch_ratio": 0.8, "pipe_outer_diameter": "100 mm", "pipe_wall": "6 mm",
                  "flight_thickness": "4 mm"},
    },
}


@pytest.fixture
def base_problem():
    return copy.deepcopy(BASE)
