# SPDX-License-Identifier: MIT
"""omniORBpy's module omniORB.URI: CosNaming names to and from their string form ("a.kind/b", with
"\\" escaping "/", "." and "\\"), and corbaname: URIs."""

from urllib.parse import quote


def _escape(text):
    return "".join("\\" + c if c in "/.\\" else c for c in text)


def nameToString(name):
    """The string form of a CosNaming name (a list of CosNaming.NameComponent)."""
    import CosNaming
    if not name:
        raise CosNaming.NamingContext.InvalidName()
    parts = []
    for component in name:
        if not component.id and not component.kind:
            parts.append(".")
        else:
            parts.append(_escape(component.id) + ("." + _escape(component.kind) if component.kind else ""))
    return "/".join(parts)


def _split(text, separator):
    """text split at the separators no backslash escapes, the escapes kept."""
    parts, current, escaped = [], "", False
    for c in text:
        if escaped:
            current += "\\" + c
            escaped = False
        elif c == "\\":
            escaped = True
        elif c == separator:
            parts.append(current)
            current = ""
        else:
            current += c
    if escaped:
        raise ValueError("a name ends with a backslash")
    parts.append(current)
    return parts


def _unescape(text):
    out, escaped = [], False
    for c in text:
        if c == "\\" and not escaped:
            escaped = True
            continue
        out.append(c)
        escaped = False
    return "".join(out)


def stringToName(sname):
    """The CosNaming name (a list of CosNaming.NameComponent) of its string form."""
    import CosNaming
    try:
        components = _split(sname, "/") if sname else []
        if not components or any(not component for component in components):
            raise ValueError(sname)
        name = []
        for component in components:
            if component == ".":
                name.append(CosNaming.NameComponent("", ""))
                continue
            pieces = _split(component, ".")
            if len(pieces) > 2:
                raise ValueError(component)
            name.append(CosNaming.NameComponent(_unescape(pieces[0]), _unescape(pieces[1]) if len(pieces) > 1 else ""))
        return name
    except ValueError:
        raise CosNaming.NamingContext.InvalidName()


def addrAndNameToURI(addr, sname):
    """A corbaname: URI of a name server's address ("host:port") and a name's string form."""
    return "corbaname:" + addr + "#" + quote(sname, safe=";/:?@&=+$,-_.!~*'()\\")
