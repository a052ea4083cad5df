// SPDX-License-Identifier: MIT
// The far end of a required service interface: filled in when the service port connects.
#ifndef RTM_CORBACONSUMER_H
#define RTM_CORBACONSUMER_H

#include <rtm/RTC.h>

#include <iostream>
#include <utility>

namespace RTC
{
/// An untyped object reference slot that a CorbaPort fills on connect and clears on disconnect.
class CorbaConsumerBase
{
public:
    CorbaConsumerBase() = default;
    CorbaConsumerBase(const CorbaConsumerBase &other) : m_objref(CORBA::Object::_duplicate(other.m_objref)) {}
    CorbaConsumerBase &operator=(const CorbaConsumerBase &other)
    {
        if (this != &other)
            m_objref = CORBA::Object::_duplicate(other.m_objref);
        return *this;
    }
    virtual ~CorbaConsumerBase() = default;

    /// Takes a reference to @p obj; false (and nothing kept) when it is nil.
    virtual bool setObject(CORBA::Object_ptr obj)
    {
        if (CORBA::is_nil(obj))
            return false;
        m_objref = CORBA::Object::_duplicate(obj);
        return true;
    }
    /// The reference held (not duplicated); nil while unconnected.
    virtual CORBA::Object_ptr getObject() { return m_objref; }
    virtual void releaseObject() { m_objref = CORBA::Object::_nil(); }
    /// Exchanges the references held with @p x.
    void swap(CorbaConsumerBase &x)
    {
        CORBA::Object_var mine = m_objref._retn();
        m_objref = x.m_objref._retn();
        x.m_objref = mine._retn();
    }

protected:
    CORBA::Object_var m_objref;
};

/**
 * A typed consumer: `m_service->operation()` calls the connected provider. Until the port is
 * connected the reference is nil and a call raises CORBA::BAD_OPERATION or similar — check with
 * CORBA::is_nil(m_service._ptr()) first.
 */
template <class ObjectType, typename ObjectTypePtr = typename ObjectType::_ptr_type,
          typename ObjectTypeVar = typename ObjectType::_var_type>
class CorbaConsumer : public CorbaConsumerBase
{
public:
    CorbaConsumer() : m_var(ObjectType::_nil()) {}
    CorbaConsumer(const CorbaConsumer &other) : CorbaConsumerBase(other), m_var(ObjectType::_duplicate(other.m_var)) {}
    CorbaConsumer &operator=(const CorbaConsumer &other)
    {
        if (this != &other) {
            CorbaConsumerBase::operator=(other);
            m_var = ObjectType::_duplicate(other.m_var);
        }
        return *this;
    }
    ~CorbaConsumer() override = default;

    /// Keeps @p obj when it is a non-nil @p ObjectType; otherwise clears the consumer and answers false.
    bool setObject(CORBA::Object_ptr obj) override
    {
        if (!CorbaConsumerBase::setObject(obj)) {
            releaseObject();
            return false;
        }
        ObjectTypeVar typed = ObjectType::_narrow(m_objref);
        if (CORBA::is_nil(typed)) {
            releaseObject();
            return false;
        }
        m_var = typed;
        return true;
    }
    /// Exchanges the references held (untyped and typed) with @p x.
    void swap(CorbaConsumer &x)
    {
        CorbaConsumerBase::swap(x);
        ObjectTypeVar mine = m_var._retn();
        m_var = x.m_var._retn();
        x.m_var = mine._retn();
    }
    ObjectTypePtr _ptr() { return m_var.inout(); }
    ObjectTypePtr operator->() { return m_var.inout(); }
    void releaseObject() override
    {
        CorbaConsumerBase::releaseObject();
        m_var = ObjectType::_nil();
    }

protected:
    ObjectTypeVar m_var;
};
} // namespace RTC

#endif // RTM_CORBACONSUMER_H
