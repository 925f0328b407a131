#!/usr/bin/env python3
"""Packs vct's binaries with the shared libraries they load, for a Linux machine without
Debian's packages (a GPU machine with only its driver): bundle/bin, bundle/lib, bundle/run.

    python3 scripts/portable_bundle.py BUILD_DIR OUT.tar.xz [--bin NAME]... [--scene FILE]...

The C and C++ runtimes and GL itself (glvnd's libEGL, libGL, libOpenGL) are left to the
target, whose driver provides GL and whose runtimes must be as new as Debian 12's or newer.
OpenImageIO links the libraries of every format it can read (video, DICOM, RAW, HEIF, OpenCV:
about 270 MB with theirs); vct reads none of those formats, so each is replaced by a stub
that exports the real library's symbols: functions return a pointer to zeroed memory (the
plugins' version queries and static constructors run at load time and must not crash),
objects are zeroed storage. Calling into a stub is a bug; nothing vct does reaches one.

`bundle/run PROGRAM ARGS` runs a bundled program with the bundled libraries first on the
library path.
"""
import argparse, os, re, shutil, subprocess, sys, tarfile, tempfile

RUNTIME = {'libc.so.6', 'libm.so.6', 'libstdc++.so.6', 'libgcc_s.so.1', 'ld-linux-x86-64.so.2',
           'libpthread.so.0', 'libdl.so.2', 'librt.so.1',
           'libEGL.so.1', 'libGL.so.1', 'libGLdispatch.so.0', 'libOpenGL.so.0', 'libGLX.so.0'}
# OpenImageIO's format libraries vct never calls; their own dependencies go with them.
STUBBED = {'libopencv_core.so.406', 'libopencv_imgproc.so.406', 'libopencv_videoio.so.406',
           'libdcmimage.so.17', 'libdcmimgle.so.17', 'libdcmdata.so.17', 'liboflog.so.17', 'libofstd.so.17',
           'libavcodec.so.59', 'libavformat.so.59', 'libavutil.so.57', 'libswscale.so.6',
           'libheif.so.1', 'libraw_r.so.20'}
LIB_DIRS = ['/lib/x86_64-linux-gnu', '/usr/lib/x86_64-linux-gnu', '/lib', '/usr/lib']


def run(*cmd):
    return subprocess.run(cmd, capture_output=True, text=True, check=True).stdout


def needed(path):
    return re.findall(r'NEEDED\)\s+Shared library: \[(.*?)\]', run('readelf', '-d', path))


def resolve(soname):
    for d in LIB_DIRS:
        p = os.path.join(d, soname)
        if os.path.exists(p):
            return p
    sys.exit(f'portable_bundle: {soname} not found in {LIB_DIRS}')


def write_stub(real, out_dir, work):
    """A library with `real`'s soname, version nodes and non-weak dynamic symbols. Weak ones
    (C++ template instances) are left out: every user has its own, and a stub's would
    interpose on them."""
    soname = re.search(r'SONAME\)\s+Library soname: \[(.*?)\]', run('readelf', '-d', real)).group(1)
    versions, by_version, seen = [], {}, set()
    for m in re.finditer(r'Flags: (\S+)\s+Index: \d+\s+Cnt: \d+\s+Name: (\S+)', run('readelf', '-V', '-W', real)):
        if 'BASE' not in m.group(1) and m.group(2) not in versions:
            versions.append(m.group(2))
    asm = ['.data', '.balign 64', 'stub_zero:', '.zero 256']
    for line in run('readelf', '--dyn-syms', '-W', real).splitlines():
        f = line.split()
        if len(f) < 8 or not f[0].endswith(':'):
            continue
        _, _, size, kind, bind, _, ndx, name = f[:8]
        if ndx in ('UND', 'ABS') or bind != 'GLOBAL' or kind not in ('FUNC', 'IFUNC', 'OBJECT', 'TLS'):
            continue
        version = None
        if '@' in name:
            name, version = re.split(r'@@?', name, maxsplit=1)
        if name in seen:
            continue
        seen.add(name)
        if version and version not in versions:
            versions.append(version)
        by_version.setdefault(version, []).append(name)
        q, n = f'"{name}"', max(int(size, 0), 1)
        if kind in ('FUNC', 'IFUNC'):
            asm += ['.text', f'.globl {q}', f'.type {q},@function', f'{q}:', 'lea stub_zero(%rip),%rax', 'ret']
        else:
            section = '.section .tbss,"awT",@nobits' if kind == 'TLS' else '.data'
            asm += [section, '.balign 16', f'.globl {q}', f'.type {q},@object', f'.size {q},{n}', f'{q}:', f'.zero {n}']
    src = os.path.join(work, soname + '.s')
    with open(src, 'w') as fh:
        fh.write('\n'.join(asm) + '\n')
    cmd = ['gcc', '-shared', '-nostdlib', '-o', os.path.join(out_dir, soname), src, '-Wl,-soname,' + soname]
    if versions:
        vmap = os.path.join(work, soname + '.map')
        with open(vmap, 'w') as fh:
            for v in versions:
                names = ' '.join(f'"{n}";' for n in by_version.get(v, []))
                fh.write(f'{v} {{ {"global: " + names if names else ""} }};\n')
        cmd.append('-Wl,--version-script=' + vmap)
    subprocess.run(cmd, check=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('build_dir')
    ap.add_argument('out')
    ap.add_argument('--bin', action='append', help='program in BUILD_DIR (default: vct and the GPU, CLI and stability tests)')
    ap.add_argument('--scene', action='append', default=[], help='a scene file to carry in bundle/scenes')
    a = ap.parse_args()
    bins = a.bin or ['vct', 'vct_tests_gpu', 'vct_tests_cli', 'vct_tests_stability']
    with tempfile.TemporaryDirectory() as work:
        root = os.path.join(work, 'bundle')
        for d in ('bin', 'lib', 'scenes'):
            os.makedirs(os.path.join(root, d))
        queue = []
        for b in bins:
            shutil.copy2(os.path.join(a.build_dir, b), os.path.join(root, 'bin', b))
            queue += needed(os.path.join(a.build_dir, b))
        done = set()
        while queue:
            n = queue.pop()
            if n in RUNTIME or n in done:
                continue
            done.add(n)
            if n in STUBBED:
                write_stub(resolve(n), os.path.join(root, 'lib'), work)
                continue
            path = resolve(n)
            shutil.copy2(path, os.path.join(root, 'lib', n))
            queue += needed(path)
        for s in a.scene:
            shutil.copy2(s, os.path.join(root, 'scenes'))
        # The tests find the sources and `vct` at the paths the build baked in: record them
        # for scripts/gpu_check.sh, which links them to the target's checkout and bundle.
        cache = open(os.path.join(a.build_dir, 'CMakeCache.txt')).read()
        source = re.search(r'^CMAKE_HOME_DIRECTORY:INTERNAL=(.*)$', cache, re.M).group(1)
        with open(os.path.join(root, 'paths'), 'w') as fh:
            fh.write(f'source={source}\nbuild={os.path.abspath(a.build_dir)}\n')
        launcher = os.path.join(root, 'run')
        with open(launcher, 'w') as fh:
            fh.write('#!/bin/sh\n# Runs a bundled program with the bundled libraries first.\n'
                     'here=$(cd "$(dirname "$0")" && pwd)\nprog=$1; shift\n'
                     'LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" exec "$here/bin/$prog" "$@"\n')
        os.chmod(launcher, 0o755)
        tmp = a.out + '.tmp'
        with tarfile.open(tmp, 'w:xz') as tar:
            tar.add(root, arcname='bundle')
        os.replace(tmp, a.out)
        print(f'{a.out}: {len(bins)} programs, {len(done)} libraries ({len(done & STUBBED)} stubbed), '
              f'{os.path.getsize(a.out) / 2**20:.1f} MiB')


if __name__ == '__main__':
    main()
