# Makes fresh HOME folders for the FreeCAD tests, so they never read or write a real user's
# settings: `cmake -DROOT=<dir> -DNAMES=app,gui -DMOD_DIR=<installed addon> -P make_test_home.cmake`.
# Each <ROOT>/<name> gets
#   .local/share/FreeCAD/Mod/AeroNC -> MOD_DIR   (FreeCAD 0.20's user Mod folder is
#                                                 $HOME/.local/share/FreeCAD/Mod)
#   .config/FreeCAD/user.cfg                     (user parameters: Path's velocity warning off,
#                                                 else a modal dialog blocks Path's activation)
cmake_minimum_required(VERSION 3.16)
foreach(var ROOT NAMES MOD_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "make_test_home.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT EXISTS "${MOD_DIR}/aeronc/__init__.py" OR NOT EXISTS "${MOD_DIR}/package.xml")
  message(FATAL_ERROR "AeroNC is not installed in ${MOD_DIR}: run `cmake --install <build>` first")
endif()
file(GLOB core "${MOD_DIR}/aeronc/_core*.so")
if(NOT core)
  message(FATAL_ERROR "${MOD_DIR}/aeronc has no _core extension: build and install first")
endif()

string(REPLACE "," ";" NAMES "${NAMES}")
foreach(name IN LISTS NAMES)
  set(home "${ROOT}/${name}")
  file(REMOVE_RECURSE "${home}")
  file(MAKE_DIRECTORY "${home}/.local/share/FreeCAD/Mod" "${home}/.config/FreeCAD")
  file(CREATE_LINK "${MOD_DIR}" "${home}/.local/share/FreeCAD/Mod/AeroNC" SYMBOLIC)
  file(WRITE "${home}/.config/FreeCAD/user.cfg" [=[<?xml version="1.0" encoding="UTF-8" standalone="no" ?>
<FCParameters>
  <FCParamGroup Name="Root">
    <FCParamGroup Name="BaseApp">
      <FCParamGroup Name="Preferences">
        <FCParamGroup Name="Mod">
          <FCParamGroup Name="Path">
            <FCBool Name="WarningSuppressVelocity" Value="1"/>
          </FCParamGroup>
        </FCParamGroup>
      </FCParamGroup>
    </FCParamGroup>
  </FCParamGroup>
</FCParameters>
]=])
endforeach()
