"""Pixels of binary PPM images (P6, 8 bits) for tests/coincident.sh.

pixels.py A B: over the pixels where A and B differ, prints how many,
then how many are red (red over twice blue) in A, blue in A, red in B,
blue in B. pixels.py A B P: over those pixels, how many of P's are more
than 32 levels off A's in some channel."""
import sys


def ppm(path):
    """The pixel bytes of a P6 image (after its four header fields)."""
    data = open(path, "rb").read()
    fields, i = [], 0
    while len(fields) < 4:
        while data[i:i + 1].isspace():
            i += 1
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        fields.append(data[i:j])
        i = j
    return data[i + 1:]


def main(paths):
    a, b = ppm(paths[0]), ppm(paths[1])
    differ = [k for k in range(0, min(len(a), len(b)), 3) if a[k:k + 3] != b[k:k + 3]]
    if len(paths) == 3:
        p = ppm(paths[2])
        print(sum(1 for k in differ if max(abs(a[k + c] - p[k + c]) for c in range(3)) > 32))
        return

    def red(img, k):
        return int(img[k] > 2 * img[k + 2])

    def blue(img, k):
        return int(img[k + 2] > 2 * img[k])

    print(len(differ), sum(red(a, k) for k in differ), sum(blue(a, k) for k in differ),
          sum(red(b, k) for k in differ), sum(blue(b, k) for k in differ))


main(sys.argv[1:])
