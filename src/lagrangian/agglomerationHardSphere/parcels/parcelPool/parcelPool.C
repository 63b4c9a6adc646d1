/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox
   \\    /   O peration     |
    \\  /    A nd           | www.openfoam.com
     \\/     M anipulation  |
-------------------------------------------------------------------------------
    Copyright (C) 2026 agglomerationHardSphere project contributors
-------------------------------------------------------------------------------
License
    This file is part of the agglomerationHardSphere extension of OpenFOAM.

    It is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by
    the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    It is distributed in the hope that it will be useful, but WITHOUT
    ANY WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License
    along with OpenFOAM.  If not, see <http://www.gnu.org/licenses/>.

\*---------------------------------------------------------------------------*/

#include "parcelPool.H"
#include "error.H"
#include <cstddef>
#include <functional>
#include <new>

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const std::size_t Foam::parcelPool::defaultSlotsPerChunk = 4096;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::parcelPool::grow()
{
    char* chunk =
        static_cast<char*>(::operator new(slotSize_*slotsPerChunk_));
    chunks_.push_back(chunk);

    // Push the slots from the last to the first: the first is handed out
    // first
    for (std::size_t i = slotsPerChunk_; i-- > 0;)
    {
        void* slot = chunk + i*slotSize_;
        *static_cast<void**>(slot) = free_;
        free_ = slot;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::parcelPool::parcelPool
(
    const std::size_t size,
    const std::size_t align,
    const std::size_t slotsPerChunk
)
:
    slotSize_
    (
        ((size < sizeof(void*) ? sizeof(void*) : size) + align - 1)
       /align*align
    ),
    slotsPerChunk_(slotsPerChunk),
    chunks_(),
    free_(nullptr),
    nUsed_(0)
{
    if
    (
        align == 0 || (align & (align - 1)) != 0
     || align > alignof(std::max_align_t) || slotsPerChunk == 0
    )
    {
        FatalErrorInFunction
            << "parcelPool of " << label(size) << " B: alignment "
            << label(align) << " must be a power of 2 up to "
            << label(alignof(std::max_align_t)) << " and slots per chunk "
            << label(slotsPerChunk) << " positive"
            << abort(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::parcelPool::~parcelPool()
{
    for (char* chunk : chunks_)
    {
        ::operator delete(chunk);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void* Foam::parcelPool::allocate()
{
    if (!free_)
    {
        grow();
    }
    void* slot = free_;
    free_ = *static_cast<void**>(slot);
    ++nUsed_;
    return slot;
}


void Foam::parcelPool::deallocate(void* p)
{
    if (!p)
    {
        return;
    }
    *static_cast<void**>(p) = free_;
    free_ = p;
    --nUsed_;
}


bool Foam::parcelPool::holds(const void* p) const
{
    const std::less<const void*> before;
    for (const char* chunk : chunks_)
    {
        const char* end = chunk + slotSize_*slotsPerChunk_;
        if (!before(p, chunk) && before(p, end))
        {
            return
                (static_cast<const char*>(p) - chunk) % slotSize_ == 0;
        }
    }
    return false;
}


// ************************************************************************* //
