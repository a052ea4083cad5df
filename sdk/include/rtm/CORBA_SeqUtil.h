// SPDX-License-Identifier: MIT
// Container helpers for CORBA sequences (length()/operator[] types), with OpenRTM-aist's names
// and semantics: iterate, search, append, insert and erase without hand-written index loops.
#ifndef CORBA_SEQUTIL_H
#define CORBA_SEQUTIL_H

#include <rtm/Manager.h>
#include <rtm/RTC.h>

#include <coil/stringutil.h>

#include <condition_variable>
#include <string>

namespace CORBA_SeqUtil
{
namespace detail
{
/// The stringified reference of `object` ("IOR:…"), made by the SDK's ORB.
std::string objectToString(CORBA::Object_ptr object);
} // namespace detail

/// Calls `f` on every element in order; returns the functor (with whatever it gathered).
template <class CorbaSequence, class Functor>
Functor for_each(CorbaSequence &seq, Functor f)
{
    const CORBA::ULong count = seq.length();
    for (CORBA::ULong i = 0; i < count; ++i)
        f(seq[i]);
    return f;
}

/// The index of the first element for which `f` is true, or -1.
template <class CorbaSequence, class Functor>
CORBA::Long find(const CorbaSequence &seq, Functor f)
{
    const CORBA::ULong count = seq.length();
    for (CORBA::ULong i = 0; i < count; ++i) {
        if (f(seq[i]))
            return static_cast<CORBA::Long>(i);
    }
    return -1;
}

/// Appends `elem` (assigned as the sequence's element type takes it: strings and references
/// given as raw pointers are adopted, as with any sequence element assignment).
template <class CorbaSequence, class SequenceElement>
void push_back(CorbaSequence &seq, SequenceElement elem)
{
    const CORBA::ULong at = seq.length();
    seq.length(at + 1);
    seq[at] = elem;
}

/// Appends every element of `seq2` to `seq1`.
template <class CorbaSequence>
void push_back_list(CorbaSequence &seq1, const CorbaSequence &seq2)
{
    const CORBA::ULong start = seq1.length();
    const CORBA::ULong added = seq2.length();
    seq1.length(start + added);
    for (CORBA::ULong i = 0; i < added; ++i)
        seq1[start + i] = seq2[i];
}

/// Inserts `elem` before position `index`; past the end it is appended.
template <class CorbaSequence, class SequenceElement>
void insert(CorbaSequence &seq, SequenceElement &elem, CORBA::ULong index)
{
    const CORBA::ULong count = seq.length();
    if (index > count) {
        push_back(seq, elem);
        return;
    }
    seq.length(count + 1);
    for (CORBA::ULong i = count; i > index; --i)
        seq[i] = seq[i - 1];
    seq[index] = elem;
}

/// The first element (the sequence must not be empty).
template <class CorbaSequence, class SequenceElement>
SequenceElement &front(CorbaSequence &seq)
{
    return seq[0];
}

/// The last element (the sequence must not be empty).
template <class CorbaSequence, class SequenceElement>
SequenceElement &back(CorbaSequence &seq)
{
    return seq[seq.length() - 1];
}

/// Removes the element at `index`, moving the later ones down; an index past the end does nothing.
template <class CorbaSequence>
void erase(CorbaSequence &seq, CORBA::ULong index)
{
    const CORBA::ULong count = seq.length();
    if (index >= count)
        return;
    for (CORBA::ULong i = index; i + 1 < count; ++i)
        seq[i] = seq[i + 1];
    seq.length(count - 1);
}

/// Removes the first element for which `f` is true, if any.
template <class CorbaSequence, class Functor>
void erase_if(CorbaSequence &seq, Functor f)
{
    const CORBA::Long index = CORBA_SeqUtil::find(seq, f);
    if (index >= 0)
        CORBA_SeqUtil::erase(seq, static_cast<CORBA::ULong>(index));
}

/// Empties the sequence.
template <class CorbaSequence>
void clear(CorbaSequence &seq)
{
    seq.length(0);
}

/// The stringified references ("IOR:…") of a sequence of object references.
template <class CorbaRefSequence>
coil::vstring refToVstring(const CorbaRefSequence &objlist)
{
    coil::vstring iors;
    const CORBA::ULong count = objlist.length();
    for (CORBA::ULong i = 0; i < count; ++i)
        iors.push_back(detail::objectToString(objlist[i]));
    return iors;
}
} // namespace CORBA_SeqUtil

#endif // CORBA_SEQUTIL_H
