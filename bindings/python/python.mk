# bindings/python/python.mk - the Python binding; included by the top Makefile.
#   make python          wheel into $(BUILD)/python/dist, installed into the venv $(BUILD)/venv
#   make install-python  install that wheel under $(PREFIX) (lib/pythonX.Y/site-packages)
# `make check-python` (in the Makefile) runs bindings/python/check.sh: builds with the
# swig wheel and with Debian's SWIG and runs tests/python. Needs a C compiler and PyPI.
PYTHON_BUILD_SH := CVM_BUILD=$(abspath $(BUILD)) CC=$(CC) PYTHON=$(PYTHON) sh bindings/python/check.sh

python:
	$(PYTHON_BUILD_SH) --build-only

install-python: python
	$(BUILD)/venv/bin/python -m pip install -q --disable-pip-version-check --no-deps \
	  --no-index --ignore-installed $(if $(DESTDIR),--root $(DESTDIR)) --prefix $(PREFIX) \
	  $(BUILD)/python/dist/cvmesh-*.whl
