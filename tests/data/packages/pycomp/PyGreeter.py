#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""A Python component's module, as a packaging fixture (not run)."""


def PyGreeterInit(manager):
    pass
