# SPDX-License-Identifier: MIT
"""Configuration listeners as OpenRTM-aist-Python names them. The component calls a parameter
listener as listener(config_set_name, config_param_name), a set listener as listener(config_set)
with the set's Properties, and a set name listener as listener(config_set_name)."""


class ConfigurationParamListener(object):
    def __call__(self, config_set_name, config_param_name):
        pass


class ConfigurationSetListener(object):
    def __call__(self, config_set):
        pass


class ConfigurationSetNameListener(object):
    def __call__(self, config_set_name):
        pass
