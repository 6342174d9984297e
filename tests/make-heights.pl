#!/usr/bin/perl
# Writes a small height field picture for tests/planar-shapes.sh: 33x25
# samples of hills and a ridge, lopsided so that a picture read upside down
# or mirrored shows, in one of the layouts POV-Ray 3.7 reads heights from
# in its own way (image_height_at).
#
# usage: make-heights.pl KIND OUT
#   png16  16-bit grey PNG (height = sample)
#   pgm    8-bit grey binary PGM (height = sample * 257, in float)
#   png8   8-bit RGB PNG: red the high byte, green the low byte
#   pal    8-bit palette PNG of 256 greys (height = index * 256)
# Exit status 0, or 2 on a usage error.
use strict;
use warnings;
use Compress::Zlib;

my ($kind, $out) = @ARGV;
unless (defined $out && $kind =~ /^(png16|pgm|png8|pal)$/) {
    print STDERR "usage: make-heights.pl png16|pgm|png8|pal OUT\n";
    exit 2;
}
my ($w, $h) = (33, 25);
# a height in 0..1 for pixel (x, y), y = 0 the top row
sub height {
    my ($x, $y) = @_;
    my ($u, $v) = ($x / ($w - 1), $y / ($h - 1));
    my $hill = exp(-(($u - 0.3)**2 + ($v - 0.35)**2) / 0.02);
    my $ridge = 0.6 * exp(-(($u + 0.5 * $v - 0.9)**2) / 0.01);
    my $ripple = 0.08 * sin(9 * $u) * cos(7 * $v);
    my $z = 0.1 + 0.7 * $hill + $ridge + $ripple;
    return $z < 0 ? 0 : $z > 1 ? 1 : $z;
}

sub chunk {
    my ($type, $data) = @_;
    return pack('N', length $data) . $type . $data . pack('N', crc32($type . $data));
}

open my $fh, '>:raw', $out or die "cannot write $out: $!\n";
if ($kind eq 'pgm') {
    print $fh "P5\n$w $h\n255\n";
    for my $y (0 .. $h - 1) {
        print $fh pack('C*', map { int(height($_, $y) * 255 + 0.5) } 0 .. $w - 1);
    }
} else {
    my ($depth, $ctype) = $kind eq 'png16' ? (16, 0) : $kind eq 'pal' ? (8, 3) : (8, 2);
    my $raw = '';
    for my $y (0 .. $h - 1) {
        $raw .= "\0";
        for my $x (0 .. $w - 1) {
            my $v = int(height($x, $y) * 65535 + 0.5);
            $raw .= $kind eq 'png16' ? pack('n', $v)
                  : $kind eq 'pal'   ? pack('C', int(height($x, $y) * 255 + 0.5))
                  :                    pack('C3', $v >> 8, $v & 255, 0);
        }
    }
    print $fh "\x89PNG\r\n\x1a\n";
    print $fh chunk('IHDR', pack('NNCCCCC', $w, $h, $depth, $ctype, 0, 0, 0));
    print $fh chunk('PLTE', pack('C*', map { ($_, $_, $_) } 0 .. 255)) if $kind eq 'pal';
    print $fh chunk('IDAT', compress($raw));
    print $fh chunk('IEND', '');
}
close $fh or die "cannot write $out: $!\n";
exit 0;
