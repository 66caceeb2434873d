"""Where `make install` puts the Python package: the folder under PREFIX that
this python3 imports from (Debian's python3 reads
PREFIX/lib/python3.X/dist-packages for PREFIX /usr/local; a python3 built
with PREFIX as its own prefix reads site-packages there), else this
python3's own site folder, so that `import ctrack` works after the install
without PYTHONPATH. Prints the folder.
    python3 python-site.py PREFIX"""
import os
import sys
import sysconfig


def main():
    prefix = os.path.abspath(sys.argv[1])
    version = "python%d.%d" % sys.version_info[:2]
    read = {os.path.realpath(p) for p in sys.path if p}
    for kind in ("dist-packages", "site-packages"):
        folder = os.path.join(prefix, "lib", version, kind)
        if os.path.realpath(folder) in read:
            print(folder)
            return
    print(sysconfig.get_path("purelib"))


if __name__ == "__main__":
    main()
