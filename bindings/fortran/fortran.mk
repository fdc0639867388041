# bindings/fortran/fortran.mk - the Fortran binding; included by the top Makefile.
#   make fortran          cvmesh.mod + libcvmesh_fortran.a (and the example) into $(BUILD)/fortran
#   make install-fortran  cvmesh.mod into $(FMODDIR), libcvmesh_fortran.a into $(PREFIX)/lib,
#                         and $(PREFIX)/lib/pkgconfig/cvmesh-fortran.pc, so that
#                         `$(FC) prog.f90 $$(pkg-config --cflags --libs cvmesh-fortran)` builds.
# A .mod file is readable only by the compiler (and major version) that wrote it, so it
# goes to a directory named after them, $(PREFIX)/include/cvmesh/$(FC_ID) (e.g. gfortran-12),
# as distributions keep one module directory per compiler.
# `make check-fortran` (in the Makefile) runs bindings/fortran/check.sh: interfaces in
# step with the header, module tests, the README snippet and examples/fortran, and that
# example once more against an installed copy found through cvmesh-fortran.pc.
ifeq ($(origin FC),default)
  FC := gfortran
endif
FC_ID := $(notdir $(FC))-$(shell $(FC) -dumpversion 2>/dev/null | cut -d. -f1)
FMODDIR := $(PREFIX)/include/cvmesh/$(FC_ID)

fortran: $(STATIC) venv
	CVM_BUILD=$(abspath $(BUILD)) FC=$(FC) PYTHON=$(VENV_PY) CVMESH_LIB=$(abspath $(STATIC)) \
	  LIBS="$(strip $(LDLIBS_LIB))" sh bindings/fortran/check.sh --build-only

install-fortran: fortran
	install -d $(DESTDIR)$(FMODDIR) $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 $(BUILD)/fortran/cvmesh.mod $(DESTDIR)$(FMODDIR)/
	install -m 644 $(BUILD)/fortran/libcvmesh_fortran.a $(DESTDIR)$(PREFIX)/lib/
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(VERSION)|' -e 's|@FMODDIR@|$(FMODDIR)|' \
	  -e 's|@FC_ID@|$(FC_ID)|' bindings/fortran/cvmesh-fortran.pc.in \
	  > $(DESTDIR)$(PREFIX)/lib/pkgconfig/cvmesh-fortran.pc
