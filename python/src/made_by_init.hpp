// Refuses a rasterlab object that Python made without running __init__
// (rasterlab.Result.__new__(rasterlab.Result)): pybind11 would hand its
// C++ methods uninitialised memory, and a crash or garbage would follow.
// Each class the module binds names itself here, right after its
// definition, so that every use of it from Python goes through the check:
//
//   struct Mesh { ... };
//   RASTERLAB_REFUSE_USE_BEFORE_INIT(py_rl::Mesh, "Mesh")
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <typeinfo>

namespace py_rl {

// Whether `object`, if it is an instance of the bound class `type`, holds a
// constructed C++ value (made by __init__, or returned from C++).
inline bool made_by_init(pybind11::handle object, const std::type_info& type) {
    pybind11::detail::type_info* info = pybind11::detail::get_type_info(type);
    if (!info || !object || !PyObject_TypeCheck(object.ptr(), info->type)) return true;
    auto* instance = reinterpret_cast<pybind11::detail::instance*>(object.ptr());
    const pybind11::detail::value_and_holder v = instance->get_value_and_holder(info, false);
    return v && v.holder_constructed();
}

template <class T, const char* Name>
struct CheckedCaster : pybind11::detail::type_caster_base<T> {
    bool load(pybind11::handle source, bool convert) {
        if (!made_by_init(source, typeid(T)))
            throw pybind11::type_error(std::string("this rasterlab.") + Name +
                                       " was made with __new__ and never initialised; make one "
                                       "the documented way");
        return pybind11::detail::type_caster_base<T>::load(source, convert);
    }
};

}  // namespace py_rl

#define RASTERLAB_REFUSE_USE_BEFORE_INIT(T, NAME)                                 \
    namespace py_rl::made_by_init_names {                                         \
    inline constexpr char T##_name[] = NAME;                                      \
    }                                                                             \
    namespace pybind11::detail {                                                  \
    template <>                                                                   \
    struct type_caster<py_rl::T>                                                  \
        : py_rl::CheckedCaster<py_rl::T, py_rl::made_by_init_names::T##_name> {}; \
    }
