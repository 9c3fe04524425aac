"""The complete examples of docs/library.md, built and run against an installed tree as a user would:
the C program with gcc and pkg-config, the C++ one with the page's CMakeLists.txt
(find_package(deltri)), the Python one from the installed module (which must find the installed
library by itself). Each must print what the page's ```text block after it says.
    library_examples.py SOURCE_DIR BUILD_DIR [SANITIZER_FLAGS]"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile


def blocks(path):
    return re.findall(r'^```(\w+)\n(.*?)^```$', open(path).read(), re.M | re.S)


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        sys.exit('FAIL: %s: exit %d\n%s%s' % (' '.join(cmd), r.returncode, r.stdout, r.stderr))
    return r.stdout


def skip_when_missing():
    """Exit 77 (CTest: skipped) when pkg-config or numpy is missing, with the command that installs it."""
    missing = [] if shutil.which('pkg-config') else ['pkg-config']
    if subprocess.run(['/usr/bin/python3', '-c', 'import numpy'], capture_output=True).returncode != 0:
        missing.append('python3-numpy')
    if missing:
        print('SKIP: missing %s; install with: sudo apt-get install -y %s' % (', '.join(missing), ' '.join(missing)))
        sys.exit(77)


def main():
    skip_when_missing()
    source, build = sys.argv[1:3]
    sanitize = sys.argv[3] if len(sys.argv) > 3 else ''
    found = blocks(os.path.join(source, 'docs', 'library.md'))
    programs = {}
    expected = []
    for language, text in found:
        if language in ('c', 'cpp', 'cmake', 'python'):
            programs[language] = text
        elif language == 'text':
            expected.append(text)
    if sorted(programs) != ['c', 'cmake', 'cpp', 'python'] or len(expected) != 3:
        sys.exit('FAIL: docs/library.md should hold one c, cpp, cmake and python block and three text blocks')
    work = tempfile.mkdtemp()
    failures = 0
    try:
        prefix = os.path.join(work, 'prefix')
        run(['cmake', '--install', build, '--prefix', prefix])
        env = dict(os.environ, PKG_CONFIG_PATH=os.path.join(prefix, 'lib', 'pkgconfig'),
                   LD_LIBRARY_PATH=os.path.join(prefix, 'lib'))
        env.pop('DELTRI_LIBRARY', None)
        for name in ('MAKEFLAGS', 'MFLAGS', 'MAKELEVEL', 'MAKEOVERRIDES', 'GNUMAKEFLAGS'):
            env.pop(name, None)  # how the surrounding make was called must not reach cmake --build
        for name, text in (('box.c', programs['c']), ('box.cpp', programs['cpp']), ('CMakeLists.txt', programs['cmake']),
                           ('box.py', programs['python'])):
            open(os.path.join(work, name), 'w').write(text)
        flags = run(['pkg-config', '--cflags', '--libs', 'deltri'], env=env).split()
        run(['gcc', os.path.join(work, 'box.c')] + sanitize.split() + flags + ['-lm', '-o', os.path.join(work, 'box_c')], env=env)
        run(['cmake', '-S', work, '-B', os.path.join(work, 'build'), '-DCMAKE_PREFIX_PATH=' + prefix,
             '-DCMAKE_CXX_FLAGS=' + sanitize], env=env)
        run(['cmake', '--build', os.path.join(work, 'build')], env=env)
        outputs = [run([os.path.join(work, 'box_c')], env=env), run([os.path.join(work, 'build', 'box')], env=env)]
        names = ['C', 'C++', 'Python']
        site = glob.glob(os.path.join(prefix, 'lib', 'python3*', 'dist-packages'))[0]
        outputs.append(run(['/usr/bin/python3', os.path.join(work, 'box.py')], env=dict(env, PYTHONPATH=site, LD_LIBRARY_PATH='')))
        for name, got, want in zip(names, outputs, expected):
            if got == want:
                print('ok   the %s example prints what docs/library.md says' % name)
            else:
                failures += 1
                print('FAIL the %s example printed:\n%sdocs/library.md says:\n%s' % (name, got, want))
    finally:
        shutil.rmtree(work)
    sys.exit(1 if failures else 0)


main()
