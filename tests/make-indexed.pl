#!/usr/bin/perl
# Writes a small colour-mapped picture for the tests of palette pictures
# (tests/exporters.sh): 16x12 pixels of a 6-entry palette in 2x2 blocks,
# entry (x/2 + 2*(y/2)) mod 6. Entries 1 and 4 have the same colour, so a
# test that reads indices tells them apart and one that reads colours
# cannot; with "trns", entry 5 is half transparent (a PNG tRNS chunk).
#
# usage: make-indexed.pl png|bmp OUT [depth] [trns]
#   png   a palette PNG (colour type 3) of bit depth 8, or 4 with "4"
#   bmp   an uncompressed 8-bit BMP with a 6-colour palette
# Exit status 0, or 2 on a usage error.
use strict;
use warnings;
use Compress::Zlib;

my ($kind, $out, @opts) = @ARGV;
die "usage: make-indexed.pl png|bmp OUT [4] [trns]\n" unless defined $out && ($kind eq 'png' || $kind eq 'bmp');
my $depth = (grep { $_ eq '4' } @opts) ? 4 : 8;
my $trns = grep { $_ eq 'trns' } @opts;
my ($w, $h) = (16, 12);
my @palette = ([200, 40, 40], [40, 160, 60], [50, 60, 200], [230, 210, 60], [40, 160, 60], [240, 240, 240]);
sub entry { my ($x, $y) = @_; return (int($x / 2) + 2 * int($y / 2)) % 6; }

open(my $fh, '>:raw', $out) or die "make-indexed.pl: cannot write $out: $!\n";
if ($kind eq 'png') {
    my $chunk = sub {
        my ($type, $data) = @_;
        return pack('N', length $data) . $type . $data . pack('N', crc32($type . $data));
    };
    my $raw = '';
    for my $y (0 .. $h - 1) {
        $raw .= "\0"; # filter type 0 (none)
        if ($depth == 8) {
            $raw .= pack('C*', map { entry($_, $y) } 0 .. $w - 1);
        } else {
            $raw .= pack('C*', map { entry(2 * $_, $y) << 4 | entry(2 * $_ + 1, $y) } 0 .. $w / 2 - 1);
        }
    }
    print $fh "\x89PNG\r\n\x1a\n",
        $chunk->('IHDR', pack('NNCCCCC', $w, $h, $depth, 3, 0, 0, 0)),
        $chunk->('PLTE', pack('C*', map { @$_ } @palette)),
        ($trns ? $chunk->('tRNS', pack('C*', 255, 255, 255, 255, 255, 128)) : ''),
        $chunk->('IDAT', compress($raw)),
        $chunk->('IEND', '');
} else {
    my $stride = int(($w + 3) / 4) * 4;
    my $offset = 14 + 40 + 4 * @palette;
    my $size = $offset + $stride * $h;
    print $fh 'BM', pack('VvvV', $size, 0, 0, $offset),
        pack('VllvvVVllVV', 40, $w, $h, 1, 8, 0, $stride * $h, 2835, 2835, scalar @palette, 0),
        pack('C*', map { ($_->[2], $_->[1], $_->[0], 0) } @palette);
    for my $y (reverse 0 .. $h - 1) { # rows from the bottom
        print $fh pack('C*', map { entry($_, $y) } 0 .. $w - 1), "\0" x ($stride - $w);
    }
}
close($fh) or die "make-indexed.pl: cannot write $out: $!\n";
