# bindings/fortran/fortran.mk - the Fortran binding; included by the top Makefile.
#   make fortran          module cvmesh.mod + libcvmesh_fortran.a into $(BUILD)/fortran
#   make check-fortran    interfaces in step with the header, module tests, examples/fortran
#   make install-fortran  cvmesh.mod into $(PREFIX)/include, libcvmesh_fortran.a into $(PREFIX)/lib
ifeq ($(origin FC),default)
  FC := gfortran
endif
FORTRAN_CHECK := BUILD=$(BUILD) FC=$(FC) PYTHON=$(PYTHON) CVMESH_LIB=$(STATIC) \
                 LIBS="-lm $(OMPFLAGS)" sh bindings/fortran/check.sh

fortran: $(STATIC)
	$(FORTRAN_CHECK) --build-only

check-fortran: $(STATIC)
	$(FORTRAN_CHECK)

install-fortran: fortran
	install -d $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/lib
	install -m 644 $(BUILD)/fortran/cvmesh.mod $(DESTDIR)$(PREFIX)/include/
	install -m 644 $(BUILD)/fortran/libcvmesh_fortran.a $(DESTDIR)$(PREFIX)/lib/
