#include "result_objects.hpp"

#include <array>
#include <cstring>
#include <initializer_list>
#include <string>

#include "cpkit/core/status.hpp"

namespace cpkit::py {
namespace {

struct Classes {
  pyb::object solve_result, residuals, attempt, certificate;
};

Classes& classes() {
  static Classes* c = new Classes();  // never destroyed: lives as long as the interpreter
  return *c;
}

/// Interned attribute names, made once.
enum Key {
  kStatus, kSolver, kZ, kW, kResiduals, kIterations, kFunctionEvals, kJacobianEvals, kSeconds,
  kCertificate, kRay, kBasis, kAttempts, kMessage,
  kNatural, kNaturalAbs, kComplementarity, kMinZ, kMinW, kWorstIndex, kScale, kZScale,
  kRounding, kFinite, kResidual, kKeyCount
};
PyObject* key(Key k) {
  static const std::array<PyObject*, kKeyCount> keys = [] {
    const char* names[kKeyCount] = {
        "status", "solver", "z", "w", "residuals", "iterations", "function_evals",
        "jacobian_evals", "seconds", "certificate", "ray", "basis", "attempts", "message",
        "natural", "natural_abs", "complementarity", "min_z", "min_w", "worst_index", "scale",
        "z_scale", "rounding", "finite", "residual"};
    std::array<PyObject*, kKeyCount> a{};
    for (int i = 0; i < kKeyCount; ++i) a[i] = PyUnicode_InternFromString(names[i]);
    return a;
  }();
  return keys[k];
}

/// Status names as Python strings, made once.
PyObject* status_name(Status s) {
  static const std::array<PyObject*, static_cast<int>(Status::kCycleDetected) + 1> names = [] {
    std::array<PyObject*, static_cast<int>(Status::kCycleDetected) + 1> a{};
    for (std::size_t i = 0; i < a.size(); ++i) {
      const auto t = to_string(static_cast<Status>(i));
      a[i] = PyUnicode_InternFromString(std::string(t).c_str());
    }
    return a;
  }();
  return names[static_cast<std::size_t>(s)];
}

/// The attributes of one result object, collected in a dict of the right size (interned keys:
/// their hashes are cached), then given to the instance as its __dict__.
class Fields {
 public:
  /// Starts from a copy of `keys` (every field once, values None): a copy of a dict without
  /// deleted entries is one block copy, and each put then replaces a value in place.
  explicit Fields(PyObject* keys) : d_(PyDict_Copy(keys)) {
    if (d_ == nullptr) throw pyb::error_already_set();
  }
  ~Fields() { Py_XDECREF(d_); }
  Fields(const Fields&) = delete;
  Fields& operator=(const Fields&) = delete;
  /// self.k = value (steals the reference to value).
  void put(Key k, PyObject* value) {
    if (value == nullptr) throw pyb::error_already_set();
    const int rc = PyDict_SetItem(d_, key(k), value);
    Py_DECREF(value);
    if (rc != 0) throw pyb::error_already_set();
  }
  /// An instance of `cls` made as object.__new__(cls) makes it (no __init__: the dataclasses
  /// are plain, not frozen, without __post_init__), holding these fields. New reference.
  PyObject* instance(const pyb::object& cls) {
    static PyObject* const no_args = PyTuple_New(0);
    PyObject* o =
        PyBaseObject_Type.tp_new(reinterpret_cast<PyTypeObject*>(cls.ptr()), no_args, nullptr);
    if (o == nullptr) throw pyb::error_already_set();
    if (PyObject_GenericSetDict(o, d_, nullptr) != 0) {
      Py_DECREF(o);
      throw pyb::error_already_set();
    }
    return o;
  }

 private:
  PyObject* d_;
};

/// A dict holding `keys` (values None), made once: the template of a result object's fields.
PyObject* key_template(std::initializer_list<Key> keys) {
  PyObject* d = PyDict_New();
  for (Key k : keys) PyDict_SetItem(d, key(k), Py_None);
  return d;
}

/// A new float64 numpy vector holding v (the numpy C API directly: no shape containers).
PyObject* numpy_vector(const Vec& v) {
  namespace d = pyb::detail;
  const d::npy_api& api = d::npy_api::get();
  Py_intptr_t dims[1] = {static_cast<Py_intptr_t>(v.size())};
  PyObject* a = api.PyArray_NewFromDescr_(api.PyArray_Type_,
                                          api.PyArray_DescrFromType_(d::npy_api::NPY_DOUBLE_), 1,
                                          dims, nullptr, nullptr, 0, nullptr);
  if (a == nullptr) throw pyb::error_already_set();
  if (v.size() > 0)
    std::memcpy(d::array_proxy(a)->data, v.data(), static_cast<std::size_t>(v.size()) * sizeof(double));
  return a;
}

PyObject* text(const std::string& s) {
  return PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "replace");
}

PyObject* new_ref(PyObject* o) {
  Py_INCREF(o);
  return o;
}

}  // namespace

void set_result_classes(pyb::object solve_result, pyb::object residuals, pyb::object attempt,
                        pyb::object certificate) {
  Classes& c = classes();
  c.solve_result = std::move(solve_result);
  c.residuals = std::move(residuals);
  c.attempt = std::move(attempt);
  c.certificate = std::move(certificate);
}

pyb::object make_solve_result(const SolveResult& r) {
  const Classes& c = classes();
  if (!c.solve_result) return to_dict(r);
  static PyObject* const result_keys = key_template(
      {kStatus, kSolver, kZ, kW, kResiduals, kIterations, kFunctionEvals, kJacobianEvals,
       kSeconds, kCertificate, kRay, kBasis, kAttempts, kMessage});
  static PyObject* const residual_keys =
      key_template({kNatural, kNaturalAbs, kComplementarity, kMinZ, kMinW, kWorstIndex, kScale,
                    kZScale, kRounding, kFinite});
  static PyObject* const attempt_keys =
      key_template({kSolver, kStatus, kResidual, kSeconds, kMessage});
  Fields d(result_keys);
  d.put(kStatus, new_ref(status_name(r.status)));
  d.put(kSolver, text(r.solver));
  d.put(kZ, numpy_vector(r.z));
  d.put(kW, numpy_vector(r.w));
  {
    Fields rd(residual_keys);
    const Residuals& x = r.residuals;
    rd.put(kNatural, PyFloat_FromDouble(x.natural));
    rd.put(kNaturalAbs, PyFloat_FromDouble(x.natural_abs));
    rd.put(kComplementarity, PyFloat_FromDouble(x.complementarity));
    rd.put(kMinZ, PyFloat_FromDouble(x.min_z));
    rd.put(kMinW, PyFloat_FromDouble(x.min_w));
    rd.put(kWorstIndex, PyLong_FromLongLong(static_cast<long long>(x.worst_index)));
    rd.put(kScale, PyFloat_FromDouble(x.scale));
    rd.put(kZScale, PyFloat_FromDouble(x.z_scale));
    rd.put(kRounding, PyFloat_FromDouble(x.rounding));
    rd.put(kFinite, PyBool_FromLong(x.finite ? 1 : 0));
    d.put(kResiduals, rd.instance(c.residuals));
  }
  d.put(kIterations, PyLong_FromLong(r.iterations));
  d.put(kFunctionEvals, PyLong_FromLong(r.function_evals));
  d.put(kJacobianEvals, PyLong_FromLong(r.jacobian_evals));
  d.put(kSeconds, PyFloat_FromDouble(r.seconds));
  if (r.certificate) {  // rare: through the dataclass's own constructor
    const pyb::dict cd = to_dict(r)["certificate"];
    d.put(kCertificate, c.certificate(**cd).release().ptr());
  } else {
    d.put(kCertificate, new_ref(Py_None));
  }
  d.put(kRay, r.ray ? numpy_vector(*r.ray) : new_ref(Py_None));
  PyObject* basis = PyList_New(static_cast<Py_ssize_t>(r.basis.size()));
  if (basis == nullptr) throw pyb::error_already_set();
  for (std::size_t i = 0; i < r.basis.size(); ++i)
    PyList_SET_ITEM(basis, static_cast<Py_ssize_t>(i), PyLong_FromLong(r.basis[i]));
  d.put(kBasis, basis);
  PyObject* attempts = PyList_New(static_cast<Py_ssize_t>(r.attempts.size()));
  if (attempts == nullptr) throw pyb::error_already_set();
  d.put(kAttempts, new_ref(attempts));  // filled below (the dict holds one reference)
  for (std::size_t i = 0; i < r.attempts.size(); ++i) {
    const Attempt& a = r.attempts[i];
    Fields ad(attempt_keys);
    ad.put(kSolver, text(a.solver));
    ad.put(kStatus, new_ref(status_name(a.status)));
    ad.put(kResidual, PyFloat_FromDouble(a.residual));
    ad.put(kSeconds, PyFloat_FromDouble(a.seconds));
    ad.put(kMessage, text(a.message));
    PyList_SET_ITEM(attempts, static_cast<Py_ssize_t>(i), ad.instance(c.attempt));
  }
  Py_DECREF(attempts);
  d.put(kMessage, text(r.message));
  return pyb::reinterpret_steal<pyb::object>(d.instance(c.solve_result));
}

}  // namespace cpkit::py
