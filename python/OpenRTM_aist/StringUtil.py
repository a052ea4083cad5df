# SPDX-License-Identifier: MIT
"""OpenRTM_aist.StringUtil: the string helpers of OpenRTM-aist-Python that components call
(normalize, eraseBlank, stringTo, …), with its names and results."""


def eraseHeadBlank(text):
    """text without its leading spaces and tabs."""
    return text.lstrip(" \t")


def eraseTailBlank(text):
    """text without its trailing spaces and tabs."""
    return text.rstrip(" \t")


def eraseBothEndsBlank(text):
    return text.strip(" \t")


def eraseBlank(text):
    """text without any space or tab."""
    return text.replace(" ", "").replace("\t", "")


def normalize(text):
    """text without blanks at its ends, in lower case, as OpenRTM compares names."""
    return eraseBothEndsBlank(text).lower()


def toBool(text, yes, no, default_value=True):
    """True for yes, False for no (compared in lower case), default_value otherwise."""
    value = normalize(text)
    if value == normalize(yes):
        return True
    if value == normalize(no):
        return False
    return default_value


def split(text, delimiter):
    """The fields of text between delimiters, each without its end blanks."""
    if not text:
        return []
    return [eraseBothEndsBlank(field) for field in text.split(delimiter)]


def _convert(kind, text):
    if kind is bool:
        value = normalize(text)
        if value in ("1", "true", "yes", "on"):
            return True
        if value in ("0", "false", "no", "off"):
            return False
        raise ValueError(text)
    if isinstance(kind, type) and issubclass(kind, (int, float)):
        return kind(text.strip())
    return text


def stringTo(_type, text):
    """(True, value) with text converted to the type of _type (a value, or a list whose element
    type is its first item's), (False, _type) when it does not convert."""
    try:
        if isinstance(_type, list):
            kind = type(_type[0]) if _type else str
            return True, [_convert(kind, field) for field in split(text, ",")]
        return True, _convert(type(_type), text)
    except (ValueError, TypeError):
        return False, _type
