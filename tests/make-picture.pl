#!/usr/bin/perl
# Writes a small true-colour picture for the tests of how pictures' colours
# are read (tests/image-gamma.sh): 8x8 pixels of mid tones, a different
# colour in each pixel (red across, green down, blue both ways), where a
# wrong gamma curve shows the most.
#
# usage: make-picture.pl png|ppm|tga|bmp OUT [gama=G] [srgb]
#   png   8-bit RGB PNG; gama=G adds a gAMA chunk of encoding gamma G (e.g.
#         0.5556 for a file encoded for 1.8), srgb an sRGB chunk
#   ppm   binary P6 of maxval 255
#   tga   uncompressed 24-bit Targa, rows from the top
#   bmp   uncompressed 24-bit BMP
# Exit status 0, or 2 on a usage error.
use strict;
use warnings;
use Compress::Zlib;

my ($kind, $out, @opts) = @ARGV;
unless (defined $out && $kind =~ /^(png|ppm|tga|bmp)$/) {
    print STDERR "usage: make-picture.pl png|ppm|tga|bmp OUT [gama=G] [srgb]\n";
    exit 2;
}
my ($gama) = map { /^gama=([0-9.]+)$/ ? $1 : () } @opts;
my $srgb = grep { $_ eq 'srgb' } @opts;
my ($w, $h) = (8, 8);
sub pixel {
    my ($x, $y) = @_;
    return (40 + 24 * $x, 50 + 22 * $y, 200 - 10 * ($x + $y));
}

open(my $fh, '>:raw', $out) or die "make-picture.pl: cannot write $out: $!\n";
if ($kind eq 'png') {
    my $chunk = sub {
        my ($type, $data) = @_;
        return pack('N', length $data) . $type . $data . pack('N', crc32($type . $data));
    };
    my $raw = '';
    for my $y (0 .. $h - 1) {
        $raw .= "\0" . pack('C*', map { pixel($_, $y) } 0 .. $w - 1); # filter type 0 (none)
    }
    print $fh "\x89PNG\r\n\x1a\n", $chunk->('IHDR', pack('NNCCCCC', $w, $h, 8, 2, 0, 0, 0)),
        (defined $gama ? $chunk->('gAMA', pack('N', int($gama * 100000 + 0.5))) : ''),
        ($srgb ? $chunk->('sRGB', pack('C', 0)) : ''), $chunk->('IDAT', compress($raw)), $chunk->('IEND', '');
} elsif ($kind eq 'ppm') {
    print $fh "P6\n$w $h\n255\n";
    for my $y (0 .. $h - 1) {
        print $fh pack('C*', map { pixel($_, $y) } 0 .. $w - 1);
    }
} elsif ($kind eq 'tga') {
    # image type 2 (true colour), 24 bits, descriptor bit 5: top row first
    print $fh pack('CCCvvCvvvvCC', 0, 0, 2, 0, 0, 0, 0, 0, $w, $h, 24, 0x20);
    for my $y (0 .. $h - 1) {
        print $fh pack('C*', map { my @p = pixel($_, $y); reverse @p } 0 .. $w - 1);
    }
} else {
    my $stride = int(($w * 3 + 3) / 4) * 4;
    my $offset = 14 + 40;
    print $fh 'BM', pack('VvvV', $offset + $stride * $h, 0, 0, $offset),
        pack('VllvvVVllVV', 40, $w, $h, 1, 24, 0, $stride * $h, 2835, 2835, 0, 0);
    for my $y (reverse 0 .. $h - 1) { # bottom row first
        my $row = pack('C*', map { my @p = pixel($_, $y); reverse @p } 0 .. $w - 1);
        print $fh $row, "\0" x ($stride - length $row);
    }
}
close($fh) or die "make-picture.pl: cannot write $out: $!\n";
exit 0;
