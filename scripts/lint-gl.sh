#!/usr/bin/env bash
# Fails if src/ uses a GL entry point outside the project's direct-state-access rules
# (STYLE.md): object editing only through glCreate*/glNamed*/glTexture*/glVertexArray*.
set -euo pipefail
cd "$(dirname "$0")/.."
banned='\b(glGen(Textures|Buffers|Framebuffers|VertexArrays|Samplers|Queries|Renderbuffers)|glBindTexture|glTexImage[123]D|glTexStorage[123]D|glTexSubImage[123]D|glBufferData|glBufferSubData|glActiveTexture|glTexParameter[if]v?|glFramebufferTexture(2D)?)\s*\('
if grep -rnE "$banned" src/; then
    echo "lint-gl: non-DSA GL calls above (see STYLE.md, 'RAII and DSA-only GL')" >&2
    exit 1
fi
# Storage is allocated only by the creation helpers, which record it for the memory report
# (gl/MemoryRegistry.h).
storage='\b(glTextureStorage[123]D(Multisample)?|glNamedBufferStorage|glNamedBufferData|glNamedRenderbufferStorage(Multisample)?)\s*\('
if grep -rnE "$storage" src/ | grep -v '^src/gl/Objects.cpp:'; then
    echo "lint-gl: storage allocated outside gl/Objects.cpp escapes the memory report" >&2
    exit 1
fi
echo "lint-gl: src/ uses direct state access only"
