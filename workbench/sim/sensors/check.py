"""Checking a model's ``<sensor>`` elements when it is spawned."""

from __future__ import annotations

import logging

from workbench.errors import SimulationError
from workbench.sim.model_spec import SimModel
from workbench.sim.sensors.spec import (
    CAMERA_TYPES,
    CONTACT_TYPES,
    IMU_TYPES,
    LASER_TYPES,
    parse_sensor,
)

_LOG = logging.getLogger("workbench.sim")
SIMULATED_TYPES = LASER_TYPES + CAMERA_TYPES + IMU_TYPES + CONTACT_TYPES


def check_sensors(model: SimModel) -> dict[str, str]:
    """Parse every sensor of ``model``; log one error line per bad one.

    Returns:
        ``{sensor XML: message}`` of the sensors that cannot be simulated for a bad
        value; their plugins are not loaded. A sensor of a type workbench does not
        simulate (``contact``, ``gps``, ...) is one warning and is not in the result.
    """
    bad: dict[str, str] = {}
    for link, xml in model.sensors:
        try:
            from lxml import etree

            kind = str(etree.fromstring(xml.encode()).get("type", "")).strip()
            if kind not in SIMULATED_TYPES:
                _LOG.warning(
                    "model '%s', link '%s': sensor type '%s' is not simulated (workbench has %s)",
                    model.name,
                    link,
                    kind,
                    ", ".join(SIMULATED_TYPES),
                )
                continue
            parse_sensor(xml, model=model.name, link=link)
        except SimulationError as error:
            message = f"{error.one_line()}; the model runs without this sensor"
            _LOG.error("%s", message)
            bad[xml] = message
    return bad
