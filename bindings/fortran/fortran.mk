# bindings/fortran/fortran.mk - the Fortran binding; included by the top Makefile.
#   make fortran          cvmesh.mod + libcvmesh_fortran.a (and the example) into $(BUILD)/fortran
#   make install-fortran  cvmesh.mod into $(PREFIX)/include, libcvmesh_fortran.a into $(PREFIX)/lib
# `make check-fortran` (in the Makefile) runs bindings/fortran/check.sh: interfaces in
# step with the header, module tests, the README snippet and examples/fortran.
ifeq ($(origin FC),default)
  FC := gfortran
endif

fortran: $(STATIC) venv
	CVM_BUILD=$(abspath $(BUILD)) FC=$(FC) PYTHON=$(VENV_PY) CVMESH_LIB=$(abspath $(STATIC)) \
	  LIBS="-llbfgs -lm $(OMPFLAGS)" sh bindings/fortran/check.sh --build-only

install-fortran: fortran
	install -d $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/lib
	install -m 644 $(BUILD)/fortran/cvmesh.mod $(DESTDIR)$(PREFIX)/include/
	install -m 644 $(BUILD)/fortran/libcvmesh_fortran.a $(DESTDIR)$(PREFIX)/lib/
