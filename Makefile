# The two commands a newcomer types: `make demo` and `make test`. Both set everything up first:
# the Debian packages glint runs (glslang, the Mesa EGL libraries), then a virtual environment
# with glint installed editable.

PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
BUILD := build
SYSTEM_PACKAGES := glslang-tools spirv-tools libegl1 libegl-mesa0 libgl1-mesa-dri

.PHONY: setup system venv demo test lint clean

setup: system venv

# Install the missing Debian packages as root; otherwise name them and stop.
system:
	@missing=""; \
	for pkg in $(SYSTEM_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$pkg 2>/dev/null | grep -q "ok installed" || missing="$$missing $$pkg"; \
	done; \
	$(PYTHON) -c "import ensurepip, venv" 2>/dev/null || missing="$$missing python3-venv"; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    echo "installing system packages:$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing >/dev/null || exit 2; \
	  else \
	    echo "glint needs these system packages:$$missing"; \
	    echo "install them with: sudo apt-get install$$missing   (then run make again)"; \
	    exit 2; \
	  fi; \
	fi

venv: $(VENV)/.installed

$(VENV)/.installed: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --disable-pip-version-check -e '.[dev]'
	touch $@

demo: setup
	@mkdir -p $(BUILD)
	$(BIN)/glint compose -o $(BUILD)/default.glsl
	$(BIN)/glint validate $(BUILD)/default.glsl
	$(BIN)/glint render $(BUILD)/default.glsl -o $(BUILD)/default.png --time 1
	@echo "shader: $(BUILD)/default.glsl (paste it into ShaderToy's Image tab)"
	@echo "image:  $(BUILD)/default.png"

test: setup
	$(BIN)/python -m pytest -q

lint: venv
	$(BIN)/ruff check .

clean:
	rm -rf $(BUILD) $(VENV) .pytest_cache .ruff_cache
