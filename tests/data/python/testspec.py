# SPDX-License-Identifier: MIT
"""The profile the test components of this folder register with."""


def component_spec(name, description):
    """OpenRTM's profile list of a Python data-flow component type name of the test category."""
    return ["implementation_id", name, "type_name", name, "description", description, "version", "1.0",
            "vendor", "RT Studio tests", "category", "test", "activity_type", "DataFlowComponent",
            "max_instance", "1", "language", "Python", "lang_type", "script", ""]
