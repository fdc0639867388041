# bindings/python/python.mk - the Python binding; included by the top Makefile.
#   make python          wheel into $(BUILD)/python/dist, installed into the venv $(BUILD)/venv
#   make check-python    build with the swig wheel and with Debian's SWIG, run tests/python
#   make install-python  install the wheel under $(PREFIX) (lib/pythonX.Y/site-packages)
# Needs a C compiler and PyPI (numpy, swig, pytest); see bindings/python/check.sh.
PYTHON_CHECK := BUILD=$(BUILD) PYTHON=$(PYTHON) sh bindings/python/check.sh

python:
	$(PYTHON_CHECK) --build-only

check-python:
	$(PYTHON_CHECK)

install-python: python
	$(BUILD)/venv/bin/python -m pip install -q --disable-pip-version-check --no-deps \
	  --no-index --ignore-installed $(if $(DESTDIR),--root $(DESTDIR)) --prefix $(PREFIX) \
	  $(BUILD)/python/dist/cvmesh-*.whl
