# SPDX-License-Identifier: MIT
"""OpenRTM_aist.CORBA_SeqUtil: helpers for IDL sequences, which are Python lists here."""


def for_each(seq, f):
    """Calls f on each element of seq in order; returns f."""
    for item in seq:
        f(item)
    return f


def push_back(seq, elem):
    seq.append(elem)


def push_back_list(seq1, seq2):
    seq1.extend(seq2)


def find(seq, f):
    """The index of the first element for which f is true, or -1."""
    for index, item in enumerate(seq):
        if f(item):
            return index
    return -1


def erase(seq, index):
    if 0 <= index < len(seq):
        del seq[index]


def clear(seq):
    del seq[:]
